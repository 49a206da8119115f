#!/usr/bin/env python3
"""An interrupted chapter leaves no half-written file: every chapter, figures on, is stopped
three times:
  - Ctrl-C: SIGINT to its whole process group (gnuplot and ffmpeg included), at the first
    temporary file that appears in its output folder (in the middle of a write);
  - a timeout: SIGTERM to the chapter alone, at the third temporary;
  - Ctrl-C again, half-way through the time a whole run takes (timed first): in its frames or
    videos for the chapters that write them.
Then two races, on the first chapter that draws figures and the first that encodes a video: a
helper (gnuplot, ffmpeg) that starts late, two seconds after the chapter has died of a SIGTERM
sent to it alone while it waited for that helper; the helper must find nowhere to write.
Then: the chapter died of that signal; no temporary (NAME.tmp-PID) is left in its folder or in
its TMPDIR, once its helpers have ended; every figure and frame there is whole (a PNG ends in
its IEND chunk, a PDF in %%EOF, a GIF in its trailer, a text file in a newline).

Usage: interrupted_runs.py BIN_DIR WORK_DIR
"""
import os
import pathlib
import shutil
import signal
import subprocess
import sys
import time

from chapter_binaries import chapter_binaries

ENDINGS = {".png": b"IEND\xaeB`\x82", ".gif": b";", ".dat": b"\n", ".gp": b"\n"}


def entries(folder):
    """Every file and folder under `folder`. A folder may vanish while it is listed (a chapter
    removes its scratch folders): os.walk skips what it can no longer read, rglob would raise."""
    for root, folders, files in os.walk(folder):
        for name in folders + files:
            yield pathlib.Path(root) / name


def temporaries(folder):
    return sorted(str(p) for p in entries(folder) if ".tmp-" in p.name)


def torn(path):
    """Why the file at `path` is not whole, or None."""
    data = path.read_bytes()
    if not data:
        return "is empty"
    if path.suffix == ".pdf":
        return None if data.rstrip().endswith(b"%%EOF") else "has no %%EOF at its end"
    ending = ENDINGS.get(path.suffix)
    return None if ending is None or data.endswith(ending) else f"does not end in {ending!r}"


def kill_group(pgid):
    try:
        os.killpg(pgid, signal.SIGKILL)
    except ProcessLookupError:
        pass  # it ended meanwhile


def group_gone(pgid, seconds):
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        try:
            os.killpg(pgid, 0)
        except ProcessLookupError:
            return True
        time.sleep(0.05)
    return False


def interrupt(binary, out, tmp, sig, whole_group, at_temporary=None, at_seconds=None, at_name=None, path=None):
    """Runs the chapter and signals it at its `at_temporary`-th temporary file, at the first
    file whose path holds `at_name`, or `at_seconds` after its start; returns the problems
    found. `path` replaces PATH, to put slow helpers first."""
    for folder in (out, tmp):
        shutil.rmtree(folder, ignore_errors=True)
        folder.mkdir(parents=True)
    name = f"{binary.name} ({signal.Signals(sig).name} to the {'group' if whole_group else 'chapter'})"
    process = subprocess.Popen([str(binary), "--quiet", "--out", str(out)], stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, start_new_session=True,
                               env=dict(os.environ, TMPDIR=str(tmp), PATH=path or os.environ["PATH"]))
    seen, started = set(), time.monotonic()

    def waiting():
        if at_name:
            return not any(at_name in str(p) for p in entries(out))
        return len(seen) < at_temporary if at_temporary else time.monotonic() - started < at_seconds
    while process.poll() is None and waiting():
        seen.update(temporaries(out))
        time.sleep(0.005)
    if process.poll() is not None:
        return [f"{name}: finished (exit {process.returncode}) before it could be stopped"]
    (os.killpg if whole_group else os.kill)(process.pid, sig)
    try:
        code = process.wait(timeout=120)
    except subprocess.TimeoutExpired:
        kill_group(process.pid)
        return [f"{name}: still running 120 s after the signal"]
    problems = []
    if code != -sig:
        problems.append(f"{name}: ended with {code}, not by the signal: {process.stderr.read().decode()[-300:]}")
    if not group_gone(process.pid, 60):
        problems.append(f"{name}: its helpers still run 60 s later")
        kill_group(process.pid)
    left = temporaries(out) + temporaries(tmp)
    if left:
        problems.append(f"{name}: temporary files left: {left[:5]}")
    files = [p for p in out.rglob("*") if p.is_file()]
    problems += [f"{name}: {p.relative_to(out)} {why}" for p in files if (why := torn(p))]
    when = at_name if at_name else f"temporary {len(seen)}" if at_temporary else f"{at_seconds:.1f} s"
    print(f"{name}: stopped at {when} ({max(seen, default='/none').rsplit('/', 1)[-1]}); "
          f"{len(files)} files kept; {'ok' if not problems else 'PROBLEMS'}", flush=True)
    return problems


def slow_helpers(folder):
    """A folder of stand-ins that wait two seconds, then run the real gnuplot or ffmpeg; the
    PATH that puts them first."""
    folder.mkdir(parents=True, exist_ok=True)
    for helper in ("gnuplot", "ffmpeg"):
        real = shutil.which(helper)
        if real:
            stand_in = folder / helper
            stand_in.write_text(f'#!/bin/sh\nsleep 2\nexec "{real}" "$@"\n')
            stand_in.chmod(0o755)
    return f"{folder}{os.pathsep}{os.environ['PATH']}"


def late_helper_races(binaries, work):
    """SIGTERM to the chapter alone while it waits for a slow gnuplot, then a slow ffmpeg."""
    path = slow_helpers(work / "slow-helpers")
    problems = []
    for helper, log_name, chapters in (("gnuplot", ".gnuplot-log", binaries[:1]),
                                       ("ffmpeg", ".ffmpeg-log", [b for b in binaries if "sprites" in b.name][:1])):
        if helper == "ffmpeg" and not shutil.which("ffmpeg"):  # optional: chapter 5 keeps its frames
            print("no ffmpeg on this machine: the late-ffmpeg race is left out", flush=True)
            continue
        if not chapters:
            problems.append(f"no chapter to race a late {helper} with")
        for binary in chapters:
            case = work / binary.name / f"late-{helper}"
            problems += interrupt(binary, case / "out", case / "tmp", signal.SIGTERM, False, at_name=log_name, path=path)
    return problems


def main(argv):
    bin_dir, work = pathlib.Path(argv[1]), pathlib.Path(argv[2]).resolve()
    binaries = chapter_binaries(bin_dir)
    problems = late_helper_races(binaries, work)
    for binary in binaries:
        for sig, whole_group, at in ((signal.SIGINT, True, 1), (signal.SIGTERM, False, 3)):
            case = work / binary.name / signal.Signals(sig).name
            problems += interrupt(binary, case / "out", case / "tmp", sig, whole_group, at_temporary=at)
        started = time.monotonic()
        whole = subprocess.run([str(binary), "--quiet", "--out", str(work / binary.name / "whole")],
                               capture_output=True, timeout=900)
        if whole.returncode != 0:
            problems.append(f"{binary.name}: a whole run exits {whole.returncode}")
            continue
        case = work / binary.name / "half-way"
        problems += interrupt(binary, case / "out", case / "tmp", signal.SIGINT, True,
                              at_seconds=(time.monotonic() - started) / 2)
    for problem in problems:
        print("FAILED:", problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
