#!/usr/bin/env python3
"""A grade measures one exercise, and the grader can both fail and pass.

The trees below are generated from the solution markers, so a new exercise is covered with no
extra work. Each is graded with `./kit grade`, the instructor's own command:

  - exercises/ as shipped scores 0 on every item, each with the placeholder's message;
  - solutions/ scores full marks;
  - exercises/ with a set S of exercises solved scores exactly the points of S: the tests of S
    pass and every other test fails. The sets are chosen so that for any two exercises i and j,
    one tree solves i and leaves j a placeholder (each exercise gets a distinct set of half the
    trees, and no such set holds another: a Sperner family). In that tree, i's test passes
    with j a placeholder (which throws), so it never calls j's code, and j's test fails, so it
    does not pass on i's code. Seven trees cover up to 35 exercises; solving one exercise a tree
    checked the same pairs with one tree an exercise;
  - solutions/ with a set of student files made uncompilable scores the total minus the points
    of the exercises written in them, and each of those reports a compile error naming its own
    file. The sets come from the same design over the files: for any two files F and G, one tree
    breaks F and not G, so G's exercises never include F, and F's error is reported as F's.

All trees are graded in one batch, as a class: the grader compiles each distinct file once for
the batch, so a file shared by several trees (a placeholder, a solution) is compiled once.

Usage: grades_isolate_exercises.py WORK_DIR [--only ID,ID]
"""
import itertools
import json
import math
import pathlib
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import exercises  # noqa: E402  (tools/exercises.py: the marker transform)

BROKEN = '#error "made uncompilable on purpose by the isolation test"\n'


def write_tree(stage, files):
    """Makes `stage` hold exactly `files`, touching only what changed (ninja reads mtimes)."""
    stage.mkdir(parents=True, exist_ok=True)
    for old in stage.iterdir():
        if old.name not in files:
            old.unlink()
    for name, text in files.items():
        target = stage / name
        if not target.exists() or target.read_text(encoding="utf-8") != text:
            target.write_text(text, encoding="utf-8")


def separating_sets(items):
    """Subsets of `items` such that for any two items a and b, one subset holds a and not b.

    Each item gets a distinct half-size set of tree numbers; no half-size set contains another,
    so a's set has a tree that b's lacks. Returns one subset of `items` per tree."""
    trees = 2
    while math.comb(trees, trees // 2) < len(items):
        trees += 1
    codes = itertools.combinations(range(trees), trees // 2)
    members = [set() for _ in range(trees)]
    for item, code in zip(items, codes):
        for tree in code:
            members[tree].add(item)
    sets = [frozenset(m) for m in members if m]
    unseparated = [(a, b) for a in items for b in items if a != b and not any(a in s and b not in s for s in sets)]
    assert not unseparated, f"no tree separates {unseparated[:3]}"
    return sets


def grade(folders, out):
    run = subprocess.run([str(ROOT / "kit"), "grade", "--out", str(out), *map(str, folders)],
                         cwd=ROOT, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"./kit grade exited {run.returncode}:\n{run.stdout}\n{run.stderr}")
    return {f.name: json.loads((out / f.name / "grade.json").read_text(encoding="utf-8")) for f in folders}


def main(argv):
    work = pathlib.Path(argv[1]).resolve()
    only = set(argv[3].split(",")) if len(argv) > 3 and argv[2] == "--only" else None
    solutions = ROOT / "solutions"
    table = {e["id"]: e for e in json.loads((ROOT / "tests/grading/points.json").read_text(encoding="utf-8"))["exercises"]}
    region_file = exercises.regions(solutions)
    total = sum(e["points"] for e in table.values())
    every = frozenset(region_file)
    classroom, out = work / "class", work / "out"
    problems, started, trees = [], time.monotonic(), []

    def expect(label, files, points, per_exercise):
        """Adds a tree to the batch: `files`, the points it must score, and `per_exercise(row)`,
        which returns a problem string or None."""
        folder = classroom / f"tree{len(trees) + 1:02d}"
        write_tree(folder, files)
        trees.append((folder, label, points, per_exercise))

    def passes_exactly(ids):
        def check(row):
            if (row["status"] == "pass") != (row["id"] in ids):
                return f"ex {row['id']} is {row['status']} ({row['message'][:160]})"
            return None
        return check

    selected = [i for i in region_file if only is None or i in only]
    # 1. From the shipped skeleton: nothing solved, then the separating sets solved.
    def placeholder(row):
        if row["status"] != "fail" or "not implemented" not in row["message"]:
            return f"ex {row['id']}: expected the placeholder's failure, got {row['status']}: {row['message'][:160]}"
        return None
    expect("exercises/ as shipped", exercises.expected_tree(solutions), 0, placeholder)
    for solved in separating_sets(selected):
        expect(f"exercises/ with ex {', '.join(sorted(solved))} solved", exercises.expected_tree(solutions, solved),
               sum(table[i]["points"] for i in solved), passes_exactly(solved))
    # 2. The reference: everything solved.
    expect("solutions/", exercises.expected_tree(solutions, every), total, passes_exactly(every))
    # 3. Files that do not compile cost only the exercises written in them.
    for names in separating_sets(sorted({region_file[i] for i in selected})):
        in_file = {i: f for i, f in region_file.items() if f in names}
        files = exercises.expected_tree(solutions, every)
        for name in names:
            files[name] = BROKEN + files[name]

        def compile_error_in_file(row, in_file=in_file):
            if row["id"] in in_file and (row["status"] != "compile error" or in_file[row["id"]] not in row["message"]):
                return (f"ex {row['id']}: expected a compile error naming {in_file[row['id']]}, got {row['status']}: "
                        f"{row['message'][:160]}")
            return passes_exactly(every - in_file.keys())(row)
        expect(f"solutions/ with {', '.join(sorted(names))} uncompilable", files,
               total - sum(table[i]["points"] for i in in_file), compile_error_in_file)

    reports = grade([folder for folder, *_ in trees], out)
    for folder, label, points, per_exercise in trees:
        report = reports[folder.name]
        found = [f"{label}: {problem}" for row in report["exercises"] if (problem := per_exercise(row))]
        if report["points"] != points:
            found.insert(0, f"{label}: expected {points} points, got {report['points']}: " +
                         "; ".join(f"ex {r['id']} {r['status']} {r['message'][:160]}" for r in report["exercises"]))
        problems.extend(found)
        print(f"{'ok  ' if not found else 'FAIL'} {label}: {report['points']} / {report['max_points']}")
    for p in problems:
        print(p, file=sys.stderr)
    print(f"{len(problems)} problems; {len(selected)} exercises checked in {len(trees)} trees, "
          f"{time.monotonic() - started:.0f} s")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
