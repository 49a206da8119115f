#!/usr/bin/env python3
"""Every exercise in tests/grading/points.json has a marked region in solutions/, in the
file the table names, and every marked region has a row in the table."""
import json
import subprocess
import sys

table = {e["id"]: e for e in json.load(open("tests/grading/points.json", encoding="utf-8"))["exercises"]}
listed = subprocess.run([sys.executable, "tools/exercises.py", "list", "solutions"],
                        check=True, capture_output=True, text=True).stdout.split("\n")
markers = {}
for line in filter(None, listed):
    exercise, path = line.split("\t")
    markers.setdefault(exercise, set()).add(path)
problems = [f"ex {i}: in points.json but no BEGIN SOLUTION region" for i in table if i not in markers]
problems += [f"ex {i}: marked in {sorted(p)} but missing from points.json" for i, p in markers.items() if i not in table]
problems += [f"ex {i}: points.json names {table[i]['file']}, markers are in {sorted(markers[i])}"
             for i in table if i in markers and table[i]["file"] not in markers[i]]
problems += [f"ex {i}: points must be a positive number" for i, e in table.items() if not e["points"] > 0]
for p in problems:
    print(p)
print(f"{len(table)} exercises, {len(markers)} marked; {len(problems)} problems")
sys.exit(1 if problems else 0)
