#!/usr/bin/env bash
# The student edition holds no solution, builds, passes the tests that apply, and self-grades.
set -euo pipefail
kit_root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=${1:?usage: student_edition.sh WORK_DIR}
rm -rf "$work"
mkdir -p "$work"
cd "$kit_root"
./kit student-edition "$work/edition"
python3 tools/student_edition.py check "$kit_root" "$work/edition"
# The check can fail: the kit itself, solutions and all, is full of solution code.
if python3 tools/student_edition.py check "$kit_root" "$kit_root" >/dev/null 2>&1; then
  echo "FAILED: the solution-code check finds nothing in the full kit"; exit 1
fi
grep -q "solves some exercises another way" "$work/edition/README.md" || { echo "FAILED: the README does not say what production code gives away"; exit 1; }

cd "$work/edition"
# Instructor-only commands refuse with a reason.
if ./kit exercises-check 2>/dev/null; then echo "FAILED: exercises-check ran without solutions/"; exit 1; fi
./kit test
# A student who solved everything grades their own copy at full marks, from the edition alone.
cp -r exercises "$work/mine"
cp "$kit_root"/solutions/*.hpp "$work/mine/"
./kit grade --out "$work/grades" "$work/mine" >/dev/null
python3 - "$work/grades/mine/grade.json" <<'PY'
import json, sys
g = json.load(open(sys.argv[1], encoding="utf-8"))
print(f"self-grade in the student edition: {g['points']} / {g['max_points']}")
sys.exit(0 if g["points"] == g["max_points"] and g["sandboxed"] else 1)
PY
echo "student edition: ok"
