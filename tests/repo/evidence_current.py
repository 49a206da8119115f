#!/usr/bin/env python3
"""The graded evidence does not depend on the Catch2 generation: the reference's graded programs,
built here with whichever Catch2 this system has (v2 or v3), run exactly the test cases and
assertions that tests/grading/expected_evidence.json records. The grader passes an exercise only on
that exact record, so a generation that counted otherwise would fail every correct submission.

Usage: evidence_current.py BUILD_DIR [CATCH2_VERSION]
"""
import json
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXPECTED = ROOT / "tests" / "grading" / "expected_evidence.json"


def differences(expected, recorded):
    """One line for each exercise or test case whose record differs."""
    lines = []
    for ident in sorted(set(expected) | set(recorded), key=str):
        if ident == "about":
            continue
        want, got = expected.get(ident), recorded.get(ident)
        if want is None or got is None:
            lines.append(f"ex {ident}: {'not expected' if want is None else 'not run'}")
            continue
        for case in sorted(set(want) | set(got)):
            if want.get(case) != got.get(case):
                lines.append(f"ex {ident}: {case!r}: expected {want.get(case)} assertions, ran {got.get(case)}")
    return lines


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    build = pathlib.Path(sys.argv[1])
    version = sys.argv[2] if len(sys.argv) == 3 else "this system's"
    with tempfile.TemporaryDirectory() as scratch:
        output = pathlib.Path(scratch) / "evidence.json"
        run = subprocess.run([sys.executable, str(ROOT / "tools" / "grade.py"), "record-evidence", str(build),
                              "--output", str(output)], capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stdout + run.stderr)
            print(f"FAILED: the reference's graded programs did not all pass under Catch2 {version}")
            return 1
        recorded = json.loads(output.read_text(encoding="utf-8"))
    expected = json.loads(EXPECTED.read_text(encoding="utf-8"))
    lines = differences(expected, recorded)
    cases = sum(len(c) for k, c in expected.items() if k != "about")
    if lines:
        print("\n".join(lines))
        print(f"FAILED: under Catch2 {version}, {len(lines)} records differ from {EXPECTED.relative_to(ROOT)}")
        return 1
    print(f"under Catch2 {version}: all {cases} graded test cases run the recorded assertions")
    return 0


if __name__ == "__main__":
    sys.exit(main())
