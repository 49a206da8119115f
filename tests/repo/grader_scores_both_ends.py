#!/usr/bin/env python3
"""The grader can fail and can pass: grading exercises/ as shipped scores 0 on every item
(and completes, with the placeholder's message), grading solutions/ scores full marks."""
import json
import pathlib
import subprocess
import sys

out = pathlib.Path(sys.argv[1])
run = subprocess.run(["./kit", "grade", "--out", str(out), "exercises", "solutions"], capture_output=True, text=True)
print(run.stdout)
print(run.stderr, file=sys.stderr)
if run.returncode != 0:
    sys.exit(f"./kit grade exited {run.returncode}")
points = json.load(open("tests/grading/points.json", encoding="utf-8"))["exercises"]
maximum = sum(e["points"] for e in points)
exercises = json.load(open(out / "exercises" / "grade.json", encoding="utf-8"))
solutions = json.load(open(out / "solutions" / "grade.json", encoding="utf-8"))
problems = []
if len(exercises["exercises"]) != len(points) or len(solutions["exercises"]) != len(points):
    problems.append("a submission was not graded on every exercise")
for row in exercises["exercises"]:
    if row["points"] != 0 or row["status"] != "fail" or "not implemented" not in row["message"]:
        problems.append(f"exercises/ ex {row['id']}: expected 0 points with the placeholder's message, got {row}")
if solutions["points"] != maximum or solutions["max_points"] != maximum:
    problems.append(f"solutions/: expected {maximum} / {maximum}, got {solutions['points']} / {solutions['max_points']}")
for row in solutions["exercises"]:
    if row["status"] != "pass":
        problems.append(f"solutions/ ex {row['id']}: {row['status']}: {row['message']}")
for p in problems:
    print(p, file=sys.stderr)
print(f"exercises: {exercises['points']} / {maximum}; solutions: {solutions['points']} / {maximum}")
sys.exit(1 if problems else 0)
