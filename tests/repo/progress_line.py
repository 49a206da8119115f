#!/usr/bin/env python3
"""The progress line: a long run shows one on a terminal (stderr a pseudo-terminal), erases it
when done, and writes none of it to stdout (the --json summary parses) nor to a stderr that is
not a terminal; KIT_PROGRESS=always and =never force it on and off.

Usage: progress_line.py BIN_DIR
"""
import json
import os
import pathlib
import pty
import select
import subprocess
import sys
import tempfile

# About 5e9 explicit Euler steps (the round-off sweep at its budget): several seconds anywhere.
LONG = ["--no-plot", "--t-end", "10"]
BAR = "round-off  ["  # the section's name, then the bar


def run(binary, args, stdout_tty, stderr_tty, progress=None):
    """Runs binary; returns (exit code, stdout, stderr, terminal) as text, where terminal is
    what reached the pseudo-terminal (stdout and/or stderr, whichever were attached to it)."""
    env = dict(os.environ)
    env.pop("KIT_PROGRESS", None)
    if progress:
        env["KIT_PROGRESS"] = progress
    master, slave = pty.openpty()
    process = subprocess.Popen([str(binary), *args], stdin=subprocess.DEVNULL, env=env,
                               stdout=slave if stdout_tty else subprocess.PIPE,
                               stderr=slave if stderr_tty else subprocess.PIPE)
    os.close(slave)
    terminal = b""
    pipes = {p: b"" for p in (process.stdout, process.stderr) if p}
    open_fds = {master: None, **{p.fileno(): p for p in pipes}}
    while open_fds:
        ready, _, _ = select.select(list(open_fds), [], [], 120)
        if not ready:
            process.kill()
            raise SystemExit(f"{binary.name} {' '.join(args)}: no output for 120 s")
        for fd in ready:
            try:
                chunk = os.read(fd, 65536)
            except OSError:  # EIO: the last process holding the terminal closed it
                chunk = b""
            if not chunk:
                del open_fds[fd]
            elif fd == master:
                terminal += chunk
            else:
                pipes[open_fds[fd]] += chunk
    os.close(master)
    code = process.wait()
    text = lambda b: b.decode("utf-8", "replace")
    return (code, text(pipes.get(process.stdout, b"")), text(pipes.get(process.stderr, b"")),
            text(terminal))


def main(argv):
    binary = pathlib.Path(argv[1]) / "01-free-fall"
    problems = []

    def check(what, condition):
        print(("ok      " if condition else "FAILED  ") + what, flush=True)
        if not condition:
            problems.append(what)

    # 1. Text on a terminal: the line appears, is erased, and the text is all there.
    code, _, _, terminal = run(binary, LONG, stdout_tty=True, stderr_tty=True)
    check("terminal run: exit 0", code == 0)
    check("terminal run: a progress line with the section, a bar, a percentage and the time left",
          BAR in terminal and "%" in terminal and " left" in terminal)
    check("terminal run: the line is erased (\\r ESC[K) before the text goes on", "\r\x1b[K" in terminal)
    check("terminal run: the text is complete", "Where round-off wins" in terminal)
    check("terminal run: the estimate is printed before the long sweep",
          "The round-off sweep takes about" in terminal)
    # Text never lands on the bar's line: whatever follows a carriage return is a redraw of the
    # line, an erase, or a new line (the terminal turns \n into \r\n).
    pieces = terminal.split("\r")[1:]
    check("terminal run: no text is written over or after the bar",
          all(p.startswith(("\x1b[K", "\n")) or not p or (p.startswith(BAR) and p.endswith("\x1b[K"))
              for p in pieces))

    # 2. --json with stdout a pipe and stderr a terminal: the line on the terminal, stdout pure.
    code, out, _, terminal = run(binary, LONG + ["--json"], stdout_tty=False, stderr_tty=True)
    check("--json run: exit 0", code == 0)
    check("--json run: the progress line is on the terminal (stderr)", BAR in terminal)
    try:
        summary = json.loads(out)
        check("--json run: the summary holds the estimate", summary["roundoff"]["estimate"]["steps"] > 1e9)
    except ValueError:
        check("--json run: stdout is one JSON object", False)
    check("--json run: no control character on stdout", "\r" not in out and "\x1b" not in out)

    # 3. stderr not a terminal (KIT_PROGRESS unset): no line anywhere.
    code, out, err, terminal = run(binary, LONG, stdout_tty=True, stderr_tty=False)
    check("stderr a pipe: exit 0", code == 0)
    check("stderr a pipe: nothing of the line on stderr", "\r" not in err and BAR not in err)
    check("stderr a pipe: nothing of the line on stdout", BAR not in terminal and "\x1b[K" not in terminal)

    # 4. The forced modes.
    code, out, err, _ = run(binary, LONG + ["--json"], stdout_tty=False, stderr_tty=False, progress="always")
    check("KIT_PROGRESS=always: the line on a piped stderr", code == 0 and BAR in err)
    check("KIT_PROGRESS=always: stdout still one JSON object", out.lstrip().startswith("{") and BAR not in out)
    code, _, _, terminal = run(binary, LONG, stdout_tty=True, stderr_tty=True, progress="never")
    check("KIT_PROGRESS=never: no line on a terminal",
          code == 0 and BAR not in terminal and "\x1b[K" not in terminal)

    # 5. Chapter 5's rendering: 60 frames at 1280x720 take about 7 s on the 2-core machine, well
    # past the bar's 1.5 s delay; the bar counts frames.
    sprites = pathlib.Path(argv[1]) / "05-sprites"
    frames = ["--frames", "60", "--width", "1280", "--height", "720", "--format", "png"]
    with tempfile.TemporaryDirectory() as out:
        code, _, _, terminal = run(sprites, frames + ["--out", out], stdout_tty=True, stderr_tty=True)
        check("chapter 5 on a terminal: exit 0", code == 0)
        check("chapter 5 on a terminal: a progress bar while the frames render",
              "the scene  [" in terminal and "%" in terminal)
        check("chapter 5 on a terminal: erased before the text goes on", "\r\x1b[K" in terminal)
        code, _, err, _ = run(sprites, frames + ["--out", out], stdout_tty=True, stderr_tty=False)
        check("chapter 5, stderr a pipe: no bar", code == 0 and "the scene  [" not in err and "\r" not in err)

    # 6. Chapter 6's runs: seconds of cloth steps; the bar names the section it counts.
    cloth = pathlib.Path(argv[1]) / "06-cloth-explicit"
    code, _, _, terminal = run(cloth, ["--no-plot", "--t-end", "8"], stdout_tty=True, stderr_tty=True)
    check("chapter 6 on a terminal: exit 0", code == 0)
    check("chapter 6 on a terminal: a progress bar while the cloth runs",
          "the explicit loop  [" in terminal and "%" in terminal)

    print(f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
