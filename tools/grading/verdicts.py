"""One exercise's verdict, from the compile, how the student's program ended, what the judge saw
(evidence.py) and the static check's findings: pass, fail, compile error, timeout, crashed or
integrity, with one line a student can act on."""
import signal

from grading import build_log, evidence
from grading.processes import died_of


def verdict(exercise, compiled, run, expected, findings):
    """(status, message) for one exercise, from what the judge saw and how the student's program ended."""
    program, log = compiled
    if program is None:
        return "compile error", build_log.first_error(log, exercise["file"])
    student = run["student"]
    if run["timed_out"] or died_of(student, signal.SIGXCPU) or died_of(run["judge"], signal.SIGXCPU):
        return "timeout", "did not finish within the time limit: an endless loop?"
    if died_of(student, signal.SIGSYS):
        return "integrity", "the program tried to start a process or a thread, which grading forbids"
    status, reason = evidence.judge(expected, run["cases"], run["end"], run["odd"], counts=False)
    if status == "pass" and run["judge"] == 0:
        own = [f for f in findings if f["severity"] == "integrity" and f["file"] == exercise["file"]]
        if own:
            return "integrity", f"static check: {own[0]['file']}:{own[0]['line']}: {own[0]['what']}"
        return "pass", ""
    if student is not None and (student < 0 or student >= 128) and student != 128 + signal.SIGKILL:
        number = -student if student < 0 else student - 128
        name = signal.Signals(number).name if number in signal.Signals._value2member_map_ else f"signal {number}"
        return "crashed", f"the program died ({name}); {build_log.first_failure(run['output'])}".rstrip("; ")
    if status == "fail" or run["judge"] not in (0, None):
        return "fail", build_log.first_failure(run["output"]) or reason
    return "fail", f"the judge did not finish: {reason}"
