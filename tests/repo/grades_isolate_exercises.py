#!/usr/bin/env python3
"""A grade measures one exercise, and the grader can both fail and pass.

The trees below are generated from the solution markers, so a new exercise is covered with no
extra work. Each is graded with `./kit grade`, the instructor's own command:

  - exercises/ as shipped scores 0 on every item, each with the placeholder's message;
  - solutions/ scores full marks;
  - for every exercise N.k: exercises/ with only N.k's regions solved scores exactly N.k's
    points: N.k's test passes with every other exercise a placeholder, so it calls no other
    exercise's code (a placeholder throws), and every other test fails, so none of them passes
    on N.k's code. The mirror sweep (solutions/ with only N.k stubbed) is not run: beyond this
    one, it could only catch a test that passes on its own exercise or, as well, on all the
    others together, or one that a third exercise's solution breaks; it took 22 grades;
  - for every file F a student edits:
      solutions/ with F made uncompilable scores the total minus the points of F's exercises,
      and each of those reports a compile error naming F.

All trees are written in turn into one staging folder that is graded in one build tree. Only the
files that differ from the previous tree are rewritten, so ninja recompiles only the graded
programs that include them: the kit's library is built once, and a run stays within minutes.

Usage: grades_isolate_exercises.py WORK_DIR [--only ID,ID]
"""
import json
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


def grade(stage, out):
    run = subprocess.run([str(ROOT / "kit"), "grade", "--out", str(out), str(stage)],
                         cwd=ROOT, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"./kit grade exited {run.returncode}:\n{run.stdout}\n{run.stderr}")
    return json.loads((out / stage.name / "grade.json").read_text(encoding="utf-8"))


def main(argv):
    work = pathlib.Path(argv[1]).resolve()
    only = set(argv[3].split(",")) if len(argv) > 3 and argv[2] == "--only" else None
    solutions = ROOT / "solutions"
    table = {e["id"]: e for e in json.loads((ROOT / "tests/grading/points.json").read_text(encoding="utf-8"))["exercises"]}
    region_file = exercises.regions(solutions)
    total = sum(e["points"] for e in table.values())
    every = frozenset(region_file)
    stage, out = work / "stage" / "submission", work / "out"
    problems, started = [], time.monotonic()

    def expect(label, files, points, per_exercise):
        """Grades `files`; `per_exercise(row)` returns a problem string or None."""
        write_tree(stage, files)
        report = grade(stage, out)
        found = [f"{label}: {problem}" for row in report["exercises"] if (problem := per_exercise(row))]
        if report["points"] != points:
            found.insert(0, f"{label}: expected {points} points, got {report['points']}: " +
                         "; ".join(f"ex {r['id']} {r['status']} {r['message'][:160]}" for r in report["exercises"]))
        problems.extend(found)
        print(f"{'ok  ' if not found else 'FAIL'} {label}: {report['points']} / {report['max_points']}"
              f"  ({time.monotonic() - started:.0f} s)", flush=True)

    def passes_exactly(ids):
        def check(row):
            if (row["status"] == "pass") != (row["id"] in ids):
                return f"ex {row['id']} is {row['status']} ({row['message'][:160]})"
            return None
        return check

    selected = [i for i in region_file if only is None or i in only]
    # 1. From the shipped skeleton: nothing solved, then one exercise solved at a time.
    def placeholder(row):
        if row["status"] != "fail" or "not implemented" not in row["message"]:
            return f"ex {row['id']}: expected the placeholder's failure, got {row['status']}: {row['message'][:160]}"
        return None
    expect("exercises/ as shipped", exercises.expected_tree(solutions), 0, placeholder)
    for ident in selected:
        expect(f"exercises/ with only ex {ident} solved", exercises.expected_tree(solutions, {ident}),
               table[ident]["points"], passes_exactly({ident}))
    # 2. The reference: everything solved.
    expect("solutions/", exercises.expected_tree(solutions, every), total, passes_exactly(every))
    # 3. One file that does not compile costs only the exercises written in it.
    for name in sorted({region_file[i] for i in selected}):
        in_file = {i for i, f in region_file.items() if f == name}
        files = exercises.expected_tree(solutions, every)
        files[name] = BROKEN + files[name]

        def compile_error_in_file(row, in_file=in_file, name=name):
            if row["id"] in in_file and (row["status"] != "compile error" or name not in row["message"]):
                return f"ex {row['id']}: expected a compile error naming {name}, got {row['status']}: {row['message'][:160]}"
            return passes_exactly(every - in_file)(row)
        expect(f"solutions/ with {name} uncompilable", files,
               total - sum(table[i]["points"] for i in in_file), compile_error_in_file)

    for p in problems:
        print(p, file=sys.stderr)
    print(f"{len(problems)} problems; {len(selected)} exercises checked in {time.monotonic() - started:.0f} s")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
