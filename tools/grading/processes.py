"""Running a command with a bounded appetite: its output into a file rather than memory, a
timeout that kills its whole process group, and no more than a megabyte of what it printed kept."""
import os
import signal
import subprocess
import tempfile

RUN_FILE_BYTES = 1 << 20  # what a student's program may write (its output)
KEPT_BYTES = 64 << 10     # of each log and output, what the reports folder keeps


def died_of(code, sig):
    """Whether a run ended by `sig`: bare, a negative return code; under bwrap, 128 + the signal."""
    return code is not None and code in (-sig, 128 + sig)


def keep_tail(path, text):
    """Writes at most KEPT_BYTES of `text` to `path`."""
    if len(text) > KEPT_BYTES:
        text = text[:KEPT_BYTES] + f"\n[… cut at {KEPT_BYTES} bytes]\n"
    path.write_text(text, encoding="utf-8")


def run_capped(command, timeout, **kwargs):
    """Runs `command` in its own session, stdin closed, output into a temporary file (a flood
    cannot exhaust the grader's memory); on timeout kills its whole group.
    Returns (returncode or None on timeout, the first megabyte of output)."""
    with tempfile.TemporaryFile() as sink:
        process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=sink, stderr=subprocess.STDOUT,
                                   start_new_session=True, **kwargs)
        try:
            code = process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
            code = None
        sink.seek(0)
        return code, sink.read(RUN_FILE_BYTES).decode("utf-8", errors="replace")
