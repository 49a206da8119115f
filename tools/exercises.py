#!/usr/bin/env python3
"""Generate exercises/ from solutions/, or check that the committed copy is current.

In solutions/, each part a student writes sits between two marker lines:

    // BEGIN SOLUTION ex 1.1: a hint for the student
    ... reference code ...
    // END SOLUTION

In exercises/, that region becomes the hint as a TODO and a placeholder that compiles
and throws kit::NotImplemented, whose message names the exercise and the file:

    // TODO(ex 1.1): a hint for the student
    throw kit::NotImplemented("ex 1.1", "explicit_euler.hpp");

Everything else is copied as it is. Usage:
    exercises.py generate SOLUTIONS EXERCISES   rewrite EXERCISES from SOLUTIONS
    exercises.py check SOLUTIONS EXERCISES      exit 1 and show the difference if stale
    exercises.py list SOLUTIONS                 print "id<TAB>file" for every region
"""
import difflib
import json
import pathlib
import re
import sys

BEGIN = re.compile(r"^(?P<indent>\s*)// BEGIN SOLUTION ex (?P<id>\d+\.\d+):\s*(?P<hint>.+?)\s*$")
END = re.compile(r"^\s*// END SOLUTION\s*$")

README = """# Exercises

This folder is generated from `solutions/` by `./kit exercises`; do not edit it in the
kit's repository. To work on the exercises, copy it somewhere of your own:

    cp -r exercises ~/my-kit-work
    ./kit build --impl ~/my-kit-work     # chapters now run your code
    ./kit grade ~/my-kit-work            # your score, exercise by exercise

Each `// TODO(ex N.k): hint` marks code to write. Until you write it, the placeholder
below the TODO throws an error naming the exercise and the file, so a chapter or a test
that needs it stops with that message instead of printing wrong numbers.

`./kit grade` compiles each file on its own, against the standard library, Eigen, {fmt} and
only the kit headers its exercises may use (`tests/grading/points.json`); nothing else of the
kit is there to include or call. (A copy made before the library took its folders includes the
old paths, `<kit/state.hpp>` for `<kit/base/state.hpp>`: those still work for this release.)
Each file may include:
"""


def readme(solutions):
    """README.md of exercises/: the text above, then each file's allowed kit headers."""
    points = pathlib.Path(solutions).resolve().parent / "tests" / "grading" / "points.json"
    rows = {}
    for e in json.loads(points.read_text(encoding="utf-8"))["exercises"] if points.exists() else []:
        ids, headers = rows.setdefault(e["file"], ([], set()))
        ids.append(e["id"])
        # The placeholder's header, and the old paths kept one release (kit/NAME.hpp forwards to
        # kit/LAYER/NAME.hpp), go without saying.
        headers.update(h for h in e["headers"] if h != "kit/base/not_implemented.hpp" and h.count("/") == 2)
    table = ["", "| file | exercises | kit headers |", "|---|---|---|"]
    table += [f"| `{name}` | {', '.join(ids)} | {', '.join(f'`<{h}>`' for h in sorted(headers)) or 'none'} |"
              for name, (ids, headers) in sorted(rows.items())]
    return README + "\n".join(table) + "\n"


class MarkerError(Exception):
    pass


def transform(text, relpath, solved=frozenset()):
    """Returns (exercise text, [exercise ids]) for one solution file. Regions whose id is in
    `solved` keep their solution code (the isolation test builds such partly solved trees)."""
    out, ids, region = [], [], None
    for number, line in enumerate(text.splitlines(keepends=True), start=1):
        begin, end = BEGIN.match(line), END.match(line)
        if region is None:
            if begin:
                region = begin
                ids.append(begin["id"])
                indent = begin["indent"]
                if begin["id"] in solved:
                    out.append(line)
                    continue
                out.append(f"{indent}// TODO(ex {begin['id']}): {begin['hint']}\n")
                out.append(f'{indent}throw kit::NotImplemented("ex {begin["id"]}", "{relpath}");\n')
            elif end or "BEGIN SOLUTION" in line:
                raise MarkerError(f"{relpath}:{number}: marker out of place: {line.strip()}")
            else:
                out.append(line)
        else:
            if begin or ("BEGIN SOLUTION" in line):
                raise MarkerError(f"{relpath}:{number}: BEGIN SOLUTION inside another region")
            if region["id"] in solved:
                out.append(line)
            if end:
                region = None
    if region is not None:
        raise MarkerError(f"{relpath}: region ex {region['id']} has no END SOLUTION")
    return "".join(out), ids


def expected_tree(solutions, solved=frozenset()):
    """{relative path: text} of exercises/, with the regions in `solved` left solved."""
    files = {"README.md": readme(solutions)}
    for path in sorted(solutions.rglob("*")):
        if path.is_file() and path.name != "README.md":
            rel = path.relative_to(solutions).as_posix()
            files[rel], _ = transform(path.read_text(encoding="utf-8"), rel, solved)
    return files


def regions(solutions):
    """{exercise id: file} for every marked region, in file order."""
    found = {}
    for path in sorted(solutions.rglob("*.hpp")):
        rel = path.relative_to(solutions).as_posix()
        for exercise in transform(path.read_text(encoding="utf-8"), rel)[1]:
            found.setdefault(exercise, rel)
    return found


def actual_tree(exercises):
    if not exercises.is_dir():
        return {}
    return {p.relative_to(exercises).as_posix(): p.read_text(encoding="utf-8")
            for p in sorted(exercises.rglob("*")) if p.is_file()}


def main(argv):
    if len(argv) < 3 or argv[1] not in ("generate", "check", "list"):
        print(__doc__, file=sys.stderr)
        return 2
    solutions = pathlib.Path(argv[2])
    try:
        if argv[1] == "list":
            for path in sorted(solutions.rglob("*.hpp")):
                rel = path.relative_to(solutions).as_posix()
                for exercise in dict.fromkeys(transform(path.read_text(encoding="utf-8"), rel)[1]):
                    print(f"{exercise}\t{rel}")
            return 0
        exercises = pathlib.Path(argv[3])
        want, have = expected_tree(solutions), actual_tree(exercises)
    except MarkerError as error:
        print(f"exercises: {error}", file=sys.stderr)
        return 2
    if argv[1] == "check":
        stale = sorted(set(want) ^ set(have) | {f for f in want if f in have and want[f] != have[f]})
        for rel in stale:
            print(f"exercises: {rel} differs from what solutions/ generates", file=sys.stderr)
            sys.stderr.writelines(difflib.unified_diff(
                have.get(rel, "").splitlines(True), want.get(rel, "").splitlines(True),
                f"exercises/{rel} (committed)", f"exercises/{rel} (generated)"))
        if stale:
            print("exercises: run './kit exercises' to regenerate; never edit exercises/ by hand",
                  file=sys.stderr)
        return 1 if stale else 0
    for rel in set(have) - set(want):
        (exercises / rel).unlink()
    for rel, text in want.items():
        target = exercises / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        if have.get(rel) != text:
            target.write_text(text, encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
