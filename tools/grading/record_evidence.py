"""`grade.py record-evidence`: the reference judges run against the reference programs at the seed
ctest uses, and each exercise's test cases and assertion counts written to
tests/grading/expected_evidence.json, what a graded run must match (evidence.py)."""
import json
import os
import pathlib
import sys
import tempfile

from grading import build_log, evidence
from grading.builds import stem_of
from grading.processes import run_capped
from grading.runs import target

REFERENCE_SEED = "20261121"  # the seed ctest and record-evidence use


def record(points, build, output):
    """Runs the reference judges of `build` and writes their cases and counts to `output`.
    Returns the exit code: 1 when a reference does not pass."""
    tests = pathlib.Path(build).resolve() / "tests"
    recorded, problems = {}, []
    for exercise in points["exercises"]:
        ident = exercise["id"]
        with tempfile.TemporaryFile() as channel:
            env = dict(os.environ, KIT_STUDENT_PROGRAM=str(tests / f"student_{stem_of(exercise)}"),
                       KIT_EVIDENCE_FD=str(channel.fileno()))
            code, output_text = run_capped([str(tests / target(ident)), "--reporter", "compact", "--rng-seed",
                                            REFERENCE_SEED], 300, env=env, pass_fds=(channel.fileno(),))
            channel.seek(0)
            cases, end, odd = evidence.parse(channel.read(evidence.READ_BYTES + 1))
        if code != 0 or end is None or odd or any(bad for _, bad in cases.values()):
            problems.append(f"ex {ident}: the reference does not pass (exit {code}): "
                            f"{build_log.first_failure(output_text)}")
        recorded[ident] = {name: passed for name, (passed, _) in cases.items()}
    if problems:
        print("\n".join(problems), file=sys.stderr)
        return 1
    text = json.dumps({"about": "Written by `./kit evidence` from the reference solutions, at the seed ctest uses: "
                                "the test cases of each graded exercise and the assertions each runs. A graded run "
                                "passes only when every one of these cases ran and passed.", **recorded},
                      indent=2, ensure_ascii=False) + "\n"
    pathlib.Path(output).write_text(text, encoding="utf-8")
    print(f"wrote {output}: {sum(len(c) for c in recorded.values())} test cases of {len(recorded)} exercises")
    return 0
