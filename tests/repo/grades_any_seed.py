#!/usr/bin/env python3
"""The reference passes every graded test at any seed, not only the one ctest uses.

A batch draws its own seed (tools/grade.py), so a test whose tolerance holds at the kit's seed
but not at another would take points from a correct student. Each judge is run against the
reference's program (the solutions) at six seeds besides ctest's.

Usage: grades_any_seed.py BUILD_DIR
"""
import json
import os
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
SEEDS = (1, 2, 977, 65537, 4294967, 987654321)


def main(argv):
    tests = pathlib.Path(argv[1]).resolve() / "tests"
    points = json.loads((ROOT / "tests/grading/points.json").read_text(encoding="utf-8"))
    problems = []
    for exercise in points["exercises"]:
        judge = tests / ("grade_ex" + exercise["id"].replace(".", "_"))
        program = tests / ("student_" + exercise["file"].removesuffix(".hpp"))
        for seed in SEEDS:
            run = subprocess.run([str(judge), "--reporter", "compact", "--rng-seed", str(seed)], capture_output=True,
                                 text=True, env=dict(os.environ, KIT_STUDENT_PROGRAM=str(program)), timeout=120)
            if run.returncode != 0:
                failed = next((l for l in run.stdout.splitlines() if "failed" in l), run.stdout[-300:])
                problems.append(f"ex {exercise['id']} at seed {seed}: {failed}")
    print(f"{len(points['exercises'])} exercises at {len(SEEDS)} seeds; {len(problems)} problems")
    for problem in problems:
        print(problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
