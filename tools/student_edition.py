#!/usr/bin/env python3
"""Write the student edition of the kit: everything a student needs, and no solution.

  student_edition.py KIT_ROOT DESTINATION [--without-production]

The edition is the kit's tracked files without solutions/ (and without .git): exercises/ is
the default implementation, `./kit run`, `./kit test` (the tests that apply without solutions)
and `./kit grade MYCOPY` work in it. The kit's own production code solves some exercises in
another form (PRODUCTION below, listed in the edition's README). With --without-production the
edition leaves those files out: chapter 4's DOPRI5 then runs on the student's own ex 4.2 and
ex 4.3 (chapters/04-adaptive-rk/adaptive_rk_methods.hpp), and the tests and benchmark of the production
DOPRI5 are not built.

`check` mode (used by the test): student_edition.py check KIT_ROOT EDITION
exits 1 when a line of any solution region appears in any file of the edition.
"""
import json
import re
import pathlib
import shutil
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import exercises  # noqa: E402

# Production code in common/ that solves an exercise another way: what it gives away.
PRODUCTION = {
    "common/include/kit/ode/dopri5.hpp": "ex 4.2 for one tableau (the Dormand-Prince stages), and ex 4.3 in use",
    "common/include/kit/ode/pi_step_control.hpp": "ex 4.3, the PI step-size law, in a latency-conscious form",
    "common/include/kit/ode/dopri5_work_method.hpp": "the production DOPRI5 in the work-precision harness",
    "tests/common/ode/test_dopri5.cpp": "ex 4.3: dopri5.f's step-size formula written out",
    "tests/bench/bench_adaptive.cpp": "the benchmark of the production DOPRI5",
}
BANNER = """
> **Student edition.** This copy has no `solutions/`: `exercises/` is the default
> implementation. Copy it (`cp -r exercises ~/my-kit-work`), work in your copy, and check it
> with `./kit grade ~/my-kit-work`. `./kit test` runs the tests that apply without solutions.
> {production}
"""
KEPT = "The kit's own production code solves some exercises another way: {given_away}."
LEFT_OUT = ("This edition leaves out the kit's production code that solves exercises another way "
            "({given_away}): chapter 4's DOPRI5 runs on your own ex 4.2 and ex 4.3.")
MIN_LINE = 20  # shorter solution lines ("return out;") are too common to mean anything
# A line of arithmetic (a * b, u + dt, …): the method itself, not bookkeeping such as
# run.step_sizes.push_back(h) that every driver of the kit writes too.
ARITHMETIC = re.compile(r"[\w)\]]\s*(?:[-+*/](?![>=+-]))\s*[\w(.]")


def tracked_files(root):
    listed = subprocess.run(["git", "ls-files", "-z"], cwd=root, capture_output=True)
    if listed.returncode == 0 and listed.stdout:
        return [p for p in listed.stdout.decode().split("\0") if p]
    return [p.relative_to(root).as_posix() for p in root.rglob("*")
            if p.is_file() and not {".git", "build"} & set(p.relative_to(root).parts)]


def write_edition(root, destination, without_production=False):
    if destination.exists():
        sys.exit(f"student-edition: {destination} exists already; name a new folder")
    for rel in tracked_files(root):
        if rel.startswith("solutions/") or not (root / rel).is_file():
            continue
        if without_production and rel in PRODUCTION:
            continue
        target = destination / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(root / rel, target)
    presets = destination / "CMakePresets.json"
    data = json.loads(presets.read_text(encoding="utf-8"))
    for preset in data["configurePresets"]:
        if preset.get("cacheVariables", {}).get("KIT_IMPL") == "solutions":
            preset["cacheVariables"]["KIT_IMPL"] = "exercises"
    presets.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    (destination / "EDITION").write_text("student\n", encoding="utf-8")
    readme = destination / "README.md"
    text = readme.read_text(encoding="utf-8")
    title_end = text.index("\n") + 1
    given_away = "; ".join(f"`{path}` ({what})" for path, what in PRODUCTION.items())
    production = (LEFT_OUT if without_production else KEPT).format(given_away=given_away)
    readme.write_text(text[:title_end] + BANNER.format(production=production) + text[title_end:], encoding="utf-8")
    print(f"student edition written to {destination}")


def solution_lines(solutions):
    """Stripped lines of arithmetic of every solution region that appear nowhere outside one."""
    inside, outside = set(), set()
    for path in sorted(solutions.rglob("*.hpp")):
        region = False
        for line in path.read_text(encoding="utf-8").splitlines():
            if exercises.BEGIN.match(line):
                region = True
            elif exercises.END.match(line):
                region = False
            elif len(line.strip()) >= MIN_LINE and (not region or ARITHMETIC.search(line)):
                (inside if region else outside).add(line.strip())
    return inside - outside


def check(root, edition):
    secret = solution_lines(root / "solutions")
    found = []
    for path in sorted(edition.rglob("*")):
        if not path.is_file() or "build" in path.relative_to(edition).parts:
            continue
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue
        lines = {l.strip() for l in text.splitlines()}
        found += [f"{path.relative_to(edition)}: {l}" for l in sorted(secret & lines)]
    if (edition / "solutions").exists():
        found.append("solutions/ is present")
    for f in found:
        print(f"solution code in the edition: {f}", file=sys.stderr)
    print(f"{len(secret)} solution lines looked for; {len(found)} found")
    return 1 if found else 0


def main(argv):
    if len(argv) == 4 and argv[1] == "check":
        return check(pathlib.Path(argv[2]).resolve(), pathlib.Path(argv[3]).resolve())
    without_production = argv[3:] == ["--without-production"]
    if len(argv) != 3 and not without_production:
        print(__doc__, file=sys.stderr)
        return 2
    write_edition(pathlib.Path(argv[1]).resolve(), pathlib.Path(argv[2]).resolve(), without_production)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
