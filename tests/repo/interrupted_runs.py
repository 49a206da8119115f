#!/usr/bin/env python3
"""An interrupted chapter leaves no half-written file: every chapter, figures on, is stopped
three times, each at a known point of its writing:
  - Ctrl-C: SIGINT to its whole process group, just before its first file is moved into place;
  - a timeout: SIGTERM to the chapter alone, before its third;
  - Ctrl-C again half-way: before the file that halves the files a whole run writes (counted in
    the figures the suite has just drawn, FIGURES_DIR/NN-name): in its frames or videos for the
    chapters that write them.
The chapter itself stops there (KIT_STOP_BEFORE_COMMIT=N makes it raise SIGSTOP, atomic_file.cpp);
the test waits until it has, sends the signal, then SIGCONT. So a busy machine cannot make the
signal late, nor let the chapter finish first.
Then four races, on the first chapter that draws figures and the first that encodes a video: a
helper (gnuplot, ffmpeg) that starts two seconds late, and meanwhile a SIGTERM to the chapter
alone (the helper must find nowhere to write) or a SIGINT to the whole group, the helper's
stand-in included.
Then: the chapter died of that signal; no temporary (NAME.tmp-PID) is left in its folder or in
its TMPDIR, once its helpers have ended (a helper still alive 60 s later is named, with its
state and command line; a zombie has ended); every figure and frame there is whole (a PNG ends
in its IEND chunk, a PDF in %%EOF, a GIF in its trailer, a text file in a newline). The
chapters run two at a time.

Usage: interrupted_runs.py BIN_DIR WORK_DIR FIGURES_DIR
"""
import concurrent.futures
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


def stat_fields(pid):
    """The fields of /proc/PID/stat after the command name (state first, process group third),
    or None once the process is gone."""
    try:
        return pathlib.Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    except (FileNotFoundError, ProcessLookupError, IndexError):
        return None


def state(pid):
    """The process's state letter (R, S, T, Z, ...), or None once it is gone."""
    fields = stat_fields(pid)
    return fields[0] if fields else None


def group_members(pgid):
    """[(pid, state, command line)] of the processes of group `pgid` that have not ended (a
    zombie has: it waits only for whoever adopted it to collect its status)."""
    members = []
    for entry in pathlib.Path("/proc").iterdir():
        fields = stat_fields(entry.name) if entry.name.isdigit() else None
        if not fields or int(fields[2]) != pgid or fields[0] == "Z":
            continue
        try:
            command = (entry / "cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace").strip()
        except (FileNotFoundError, ProcessLookupError):
            continue
        members.append((int(entry.name), fields[0], command))
    return members


def group_gone(pgid, seconds):
    """None once every process of the group has ended, or those still alive after `seconds`."""
    deadline = time.monotonic() + seconds
    while True:
        alive = group_members(pgid)
        if not alive or time.monotonic() > deadline:
            return alive or None
        time.sleep(0.05)


def wait_until_stopped(process):
    """True once the chapter has stopped itself (state T); False if it ended first."""
    while process.poll() is None:
        if state(process.pid) == "T":
            return True
        time.sleep(0.005)
    return False


def interrupt(binary, out, tmp, sig, whole_group, stop_at=None, at_name=None, path=None):
    """Runs the chapter and signals it before its `stop_at`-th file is moved into place, or at
    the first file whose path holds `at_name`; returns the problems found. `path` replaces PATH,
    to put slow helpers first."""
    for folder in (out, tmp):
        shutil.rmtree(folder, ignore_errors=True)
        folder.mkdir(parents=True)
    name = f"{binary.name} ({signal.Signals(sig).name} to the {'group' if whole_group else 'chapter'})"
    env = dict(os.environ, TMPDIR=str(tmp), PATH=path or os.environ["PATH"])
    env.pop("KIT_STOP_BEFORE_COMMIT", None)
    if stop_at:
        env["KIT_STOP_BEFORE_COMMIT"] = str(stop_at)
    process = subprocess.Popen([str(binary), "--quiet", "--out", str(out)], stdout=subprocess.DEVNULL,
                               stderr=subprocess.PIPE, start_new_session=True, env=env)
    send = os.killpg if whole_group else os.kill
    if stop_at:
        if not wait_until_stopped(process):
            return [f"{name}: finished (exit {process.returncode}) before its file {stop_at}: "
                    f"{process.stderr.read().decode()[-300:]}"]
        send(process.pid, sig)  # pending until the chapter runs again
        send(process.pid, signal.SIGCONT)
    else:
        while process.poll() is None and not any(at_name in str(p) for p in entries(out)):
            time.sleep(0.005)
        if process.poll() is not None:
            return [f"{name}: finished (exit {process.returncode}) before {at_name} appeared"]
        send(process.pid, sig)
    try:
        code = process.wait(timeout=120)
    except subprocess.TimeoutExpired:
        kill_group(process.pid)
        return [f"{name}: still running 120 s after the signal"]
    problems = []
    if code != -sig:
        problems.append(f"{name}: ended with {code}, not by the signal: {process.stderr.read().decode()[-300:]}")
    alive = group_gone(process.pid, 60)
    if alive:
        problems.append(f"{name}: its helpers still run 60 s later: {alive}")
        kill_group(process.pid)
    left = temporaries(out) + temporaries(tmp)
    if left:
        problems.append(f"{name}: temporary files left: {left[:5]}")
    files = [p for p in out.rglob("*") if p.is_file()]
    problems += [f"{name}: {p.relative_to(out)} {why}" for p in files if (why := torn(p))]
    when = f"when {at_name} appeared" if at_name else f"before file {stop_at}"
    print(f"{name}: stopped {when}; {len(files)} files kept; {'ok' if not problems else 'PROBLEMS'}", flush=True)
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
    """While the chapter waits for a slow gnuplot, then a slow ffmpeg: SIGTERM to the chapter
    alone, and SIGINT to its whole group."""
    path = slow_helpers(work / "slow-helpers")
    problems = []
    for helper, log_name, chapters in (("gnuplot", ".gnuplot-log", binaries[:1]),
                                       ("ffmpeg", ".ffmpeg-log", [b for b in binaries if "sprites" in b.name][:1])):
        if helper == "ffmpeg" and not shutil.which("ffmpeg"):  # optional: chapter 5 keeps its frames
            print("no ffmpeg on this machine: the late-ffmpeg races are left out", flush=True)
            continue
        if not chapters:
            problems.append(f"no chapter to race a late {helper} with")
        for binary in chapters:
            for sig, whole_group in ((signal.SIGTERM, False), (signal.SIGINT, True)):
                case = work / binary.name / f"late-{helper}-{signal.Signals(sig).name}"
                problems += interrupt(binary, case / "out", case / "tmp", sig, whole_group, at_name=log_name,
                                      path=path)
    return problems


def chapter_cases(binary, work, figures):
    """The three stops of one chapter."""
    written = [p for p in (figures / binary.name).rglob("*") if p.is_file()] if (figures / binary.name).is_dir() else []
    if not written:
        return [f"{binary.name}: no figures in {figures / binary.name} to count a whole run's files by"]
    problems = []
    for sig, whole_group, stop_at, label in ((signal.SIGINT, True, 1, "first"), (signal.SIGTERM, False, 3, "third"),
                                             (signal.SIGINT, True, max(1, len(written) // 2), "half-way")):
        case = work / binary.name / label
        problems += interrupt(binary, case / "out", case / "tmp", sig, whole_group, stop_at=stop_at)
    return problems


def main(argv):
    # Started in the background by a shell without job control, this process would ignore SIGINT,
    # and so would the chapters it starts (an ignored signal stays ignored across exec; the
    # chapters then rightly leave it so). A handler of our own is reset to the default in them.
    signal.signal(signal.SIGINT, signal.default_int_handler)
    bin_dir, work, figures = pathlib.Path(argv[1]), pathlib.Path(argv[2]).resolve(), pathlib.Path(argv[3])
    binaries = chapter_binaries(bin_dir)
    problems = late_helper_races(binaries, work)
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for found in pool.map(lambda binary: chapter_cases(binary, work, figures), binaries):
            problems += found
    for problem in problems:
        print("FAILED:", problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
