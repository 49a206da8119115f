#!/usr/bin/env python3
"""Regression cases: requests that once ended in exit 1, a hang, a shell command run, or a
half-written file. Each runs as a user would, figures included, and must end in a reported
result (exit 0) or a refusal (exit 2), print no inf or nan, and leave no temporary file.

Usage: extreme_cases.py BIN_DIR WORK_DIR
"""
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys
import time

CASES = [  # (chapter, flags, expected exit code)
    ("01-free-fall", ["--x0", "3.7", "--v0", "-1.3", "--g", "-4.2", "--dt", "0.013", "--t-end", "6.721"], 0),
    ("01-free-fall", ["--t-end", "10000", "--dt", "0.01", "--dt-min", "0.001"], 0),
    ("01-free-fall", ["--dt", "1e-300", "--t-end", "1"], 2),
    ("02-spring-stability", ["--t-end", "1e5", "--dt", "0.1"], 0),
    ("02-spring-stability", ["--stiffness", "1e15", "--mass", "1e-6", "--damping", "1e12"], 0),
    ("02-spring-stability", ["--dt", "1e-16", "--t-end", "10000"], 2),
    ("03-rk2", ["--t-end", "1e-300"], 0),
    ("03-rk2", ["--damping", "1e12"], 0),
    ("03-rk2", ["--stiffness", "1e-6", "--mass", "1e6", "--t-end", "1e4"], 0),
    ("03-rk2", ["--periods", "100000"], 0),
    ("04-adaptive-rk", ["--mu", "10000"], 0),
    ("05-sprites", ["--max-particles", "1", "--frames", "30"], 0),
    ("05-sprites", ["--width", "16", "--height", "16", "--frames", "10"], 0),
    ("05-sprites", ["--scene", "fire-and-smoke", "--fps", "1", "--integrator", "euler", "--frames", "30"], 0),
    ("05-sprites", ["--scene", str(pathlib.Path(__file__).parent / "sprite_scenes" / "extreme.toml")], 0),
    ("05-sprites", ["--scene", str(pathlib.Path(__file__).parent / "sprite_scenes" / "extreme.toml"),
                    "--integrator", "euler", "--width", "7680", "--height", "4320"], 2),  # km-wide sprites: hours
    # Cloth: a step that explodes at once (figures and frames of an exploded sheet), the smallest
    # sheet, explicit Euler past its limit over the sphere, and a sheet too large for the machine.
    # The cases are about the scene's runs: --quick shrinks only the fixed experiments beside them
    # (chapter 6's stability table to 8 nodes across, its sweeps to N = 32), as in the flag table.
    ("06-cloth-explicit", ["--quick", "--dt", "1", "--frames", "3"], 0),
    ("06-cloth-explicit", ["--quick", "--resolution", "2", "--frames", "2", "--t-end", "0.5"], 0),
    ("06-cloth-explicit", ["--quick", "--scene", "drape", "--integrator", "explicit-euler", "--dt", "0.01",
                           "--t-end", "1", "--frames", "5"], 0),
    ("06-cloth-explicit", ["--resolution", "100000"], 2),
    # Implicit cloth: a one-second step, the smallest sheet, an explicit method at the implicit
    # step (a reported divergence), the clamp off (a reported solver failure or a run), Liu and
    # Newton at their extremes, and a sheet too large for the machine. The step and the sheet
    # shape the scene alone (--quick); the method, the clamp and the solver apply to every
    # section, so those cases run the fixed experiments at their full sizes.
    ("07-cloth-implicit", ["--quick", "--dt", "1", "--frames", "3"], 0),
    ("07-cloth-implicit", ["--quick", "--resolution", "2", "--frames", "2", "--t-end", "0.5"], 0),
    ("07-cloth-implicit", ["--integrator", "symplectic-euler", "--dt", "0.0333", "--t-end", "1", "--frames", "3"], 0),
    ("07-cloth-implicit", ["--no-clamp", "--solver", "cg", "--t-end", "1", "--frames", "3"], 0),
    ("07-cloth-implicit", ["--no-clamp", "--t-end", "1", "--frames", "3"], 0),
    ("07-cloth-implicit", ["--integrator", "newton", "--iterations", "1", "--cg-tol", "0.5", "--t-end", "0.5"], 0),
    ("07-cloth-implicit", ["--integrator", "liu", "--iterations", "1", "--dt", "1", "--t-end", "3"], 0),
    ("07-cloth-implicit", ["--resolution", "100000"], 2),
    # Rigid bodies: the lecture's step on R diverging (frames of an exploded body), a spin of 1.7e4
    # rad/s that overflows RK4 and stalls the midpoint's fixed point, and a run too long to make.
    ("08-rigid-bodies", ["--integrator", "euler-R", "--dt", "0.1", "--t-end", "10", "--frames", "5"], 0),
    ("08-rigid-bodies", ["--omega0", "1e4,1e4,1e4", "--t-end", "1", "--frames", "3"], 0),
    ("08-rigid-bodies", ["--dt", "1e-9", "--t-end", "1000"], 2),
    # A beam that would sag 1.5e5 times its length: Newton fails even in 64 load steps, and says so.
    ("09-continuum", ["--young", "1e3", "--density", "1e5", "--frames", "3"], 0),
    ("09-continuum", ["--young", "1e12", "--t-end", "0.01", "--frames", "3"], 0),
    ("09-continuum", ["--integrator", "explicit", "--dt", "0.1", "--resolution", "128", "--t-end", "100"], 0),
    ("09-continuum", ["--model", "linear", "--integrator", "implicit", "--mesh", "irregular", "--resolution", "2",
                      "--frames", "2"], 0),
    ("09-continuum", ["--resolution", "128", "--integrator", "implicit", "--t-end", "100"], 2),
]


def process_state(pid):
    """The state letter of /proc/PID/stat (R, S, T, ...), or None once the process is gone."""
    try:
        return pathlib.Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except (OSError, IndexError):
        return None


def leftovers(folder):
    return [p.name for p in pathlib.Path(folder).rglob("*") if ".tmp-" in p.name]


def sigterm_mid_write(bin_dir, out):
    """The problems of a run stopped by a timeout (SIGTERM) while a figure is half-written: it must
    leave no temporary. The chapter stops itself (SIGSTOP) before its first file is renamed into
    place, while that file is a temporary (KIT_STOP_BEFORE_COMMIT, atomic_file.cpp): the signal
    lands there whatever the machine's load. (Polling the folder for a temporary missed it on a
    busy machine.)"""
    problems = []
    process = subprocess.Popen([str(bin_dir / "02-spring-stability"), "--quiet", "--out", str(out)],
                               start_new_session=True, env=dict(os.environ, KIT_STOP_BEFORE_COMMIT="1"))
    deadline = time.monotonic() + 120
    while process.poll() is None and process_state(process.pid) != "T" and time.monotonic() < deadline:
        time.sleep(0.002)
    caught = process.poll() is None and process_state(process.pid) == "T" and bool(leftovers(out))
    process.send_signal(signal.SIGTERM)  # pending until the chapter runs again
    process.send_signal(signal.SIGCONT)
    code = process.wait(timeout=60)
    if not caught:
        problems.append(f"never saw the chapter stopped with a temporary file to interrupt (exit {code})")
    elif code != -signal.SIGTERM:
        problems.append(f"SIGTERM mid-write: exit {code}, expected death by SIGTERM")
    elif leftovers(out):
        problems.append(f"SIGTERM mid-write left {leftovers(out)}")
    return problems


def main(argv):
    bin_dir, work = pathlib.Path(argv[1]), pathlib.Path(argv[2])
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    problems = []
    for number, (chapter, flags, expected) in enumerate(CASES):
        out = work / f"case{number}"
        started = time.monotonic()
        done = subprocess.run([str(bin_dir / chapter), "--format", "png", "--out", str(out), *flags],
                              capture_output=True, text=True, timeout=600)
        what = f"{chapter} {' '.join(flags)}"
        print(f"exit {done.returncode} in {time.monotonic() - started:.1f} s: {what}", flush=True)
        if done.returncode != expected:
            problems.append(f"{what}: exit {done.returncode}, expected {expected}: {done.stderr.strip()[:300]}")
        if re.search(r"(?<![\w-])-?(inf|nan)\b", done.stdout, re.IGNORECASE):
            problems.append(f"{what}: prints inf or nan")
        if expected == 2 and out.exists():
            problems.append(f"{what}: a refused run created {out}")
        if leftovers(out):
            problems.append(f"{what}: left {leftovers(out)}")

    # Relative --out, and --out with shell syntax: written literally, nothing run.
    for name in ["relative-out", "$(touch injected)`touch injected2`"]:
        done = subprocess.run([str((bin_dir / "01-free-fall").resolve()), "--quiet", "--format", "png", "--out", name],
                              cwd=work, capture_output=True, text=True)
        if done.returncode != 0 or not (work / name / "trajectories.png").exists():
            problems.append(f"--out {name!r}: exit {done.returncode}, figures missing: {done.stderr.strip()[:300]}")
    if (work / "injected").exists() or (work / "injected2").exists():
        problems.append("--out with $(...) or backticks ran a shell command")

    # A bad --out is refused before anything is computed.
    (work / "a-file").write_text("x")
    for bad in ["", str(work / "a-file"), str(work / "a-file" / "below")]:
        done = subprocess.run([str(bin_dir / "04-adaptive-rk"), "--out", bad], capture_output=True, text=True, timeout=60)
        if done.returncode != 2 or "--out" not in done.stderr:
            problems.append(f"--out {bad!r}: exit {done.returncode}, expected 2 naming --out")

    problems += sigterm_mid_write(bin_dir, work / "killed")

    for p in problems:
        print(p, file=sys.stderr)
    print(f"{len(CASES)} cases; {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
