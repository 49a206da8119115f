"""The evidence a verdict needs: what the graded test process wrote on the channel the grader
set up (tests/support/catch_main.cpp writes it), against what the reference solution's run
wrote (tests/grading/expected_evidence.json).

An exercise passes only when every expected test case ended with no failed assertion and its
expected number of passed assertions, no unexpected case ran, and the run reached its end.
Anything less, with a process that still said "success", is an integrity failure."""
import json
import pathlib


READ_BYTES = 1 << 20  # more evidence than any honest run writes is itself a finding


def read(path):
    """parse() of the evidence file at `path` (nothing when it does not exist)."""
    path = pathlib.Path(path)
    if not path.exists():
        return {}, None, []
    with open(path, "rb") as f:
        return parse(f.read(READ_BYTES + 1))


def parse(data):
    """{case name: (passed, failed)} and the end record (passed, failed), or None; plus the
    inconsistencies an honest run never shows (a case twice, a line after the end, totals that
    disagree, unreadable lines), as a list of strings."""
    cases, end, odd = {}, None, []
    text = data.decode("utf-8", errors="replace")
    if len(text) > READ_BYTES:
        odd.append("the evidence is larger than any run writes")
    for line in text.splitlines():
        parts = line.split("\t")
        try:
            if end is not None:
                odd.append("a record after the end of the run")
            elif parts[0] == "case" and len(parts) == 4:
                if parts[1] in cases:
                    odd.append(f"test case '{parts[1]}' reported twice")
                cases[parts[1]] = (int(parts[2]), int(parts[3]))
            elif parts[0] == "end" and len(parts) == 3:
                end = (int(parts[1]), int(parts[2]))
            else:
                odd.append("a line that is not a record")
        except ValueError:
            odd.append("a record with a count that is not a number")
    if end is not None and end != (sum(c[0] for c in cases.values()), sum(c[1] for c in cases.values())):
        odd.append("the run's totals disagree with its test cases")
    return cases, end, odd


def load_expected(path):
    return json.loads(pathlib.Path(path).read_text(encoding="utf-8"))


def judge(expected, cases, end, odd=(), counts=True):
    """(status, reason) from the evidence alone: pass, fail or integrity. With counts=False the
    assertions each case ran are not compared with the reference's: on a batch's own seed they
    differ (a case draws its sizes from the seed), and the judge that counts them is the kit's."""
    if odd:
        return "integrity", f"the evidence is not what a test run writes: {odd[0]}"
    failed = [name for name, (_, bad) in cases.items() if bad > 0]
    if failed:
        return "fail", f"{len(failed)} test case(s) failed: {failed[0]}"
    missing = [name for name in expected if name not in cases]
    if missing:
        return "integrity", (f"{len(missing)} of {len(expected)} expected test cases never finished "
                             f"(first: '{missing[0]}'): the process ended early or skipped them")
    extra = [name for name in cases if name not in expected]
    if extra:
        return "integrity", f"unexpected test case '{extra[0]}' ran"
    for name, count in expected.items():
        if cases[name][0] == 0 or (counts and cases[name][0] != count):
            return "integrity", f"'{name}' ran {cases[name][0]} assertions, the reference runs {count}"
    if end is None:
        return "integrity", "the test run never reached its end"
    return "pass", ""
