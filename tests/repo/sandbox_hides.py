#!/usr/bin/env python3
"""The grader's sandbox hides what it promises to hide, whatever the student code does with it.

Runs shell commands through grading.sandbox exactly as the grader runs a graded program, with a
grade tree of its own, and checks from inside: the kit's solutions/ and .git are empty, another
submission and the grader's home are invisible, the kit and the file system are read-only, the
environment holds no secret, there is no network, and only the tree is writable during a build.

Usage: sandbox_hides.py WORK_DIR
"""
import os
import pathlib
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
from grading.sandbox import TEST_MEMORY, Sandbox  # noqa: E402


def main(argv):
    work = pathlib.Path(argv[1]).resolve()
    shutil.rmtree(work, ignore_errors=True)
    tree, classmate = work / "out" / "me", work / "class" / "classmate"
    tree.mkdir(parents=True)
    classmate.mkdir(parents=True)
    (classmate / "rk4.hpp").write_text("a classmate's work\n")
    os.environ["KIT_TEST_SECRET"] = "do-not-leak"
    sandbox = Sandbox(ROOT, hidden=[work / "out", classmate])

    def inside(script, writable=False):
        command = sandbox.wrap(["sh", "-c", script], tree, writable, TEST_MEMORY)
        done = subprocess.run(command, capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=60)
        return done.returncode, done.stdout.strip()

    checks = [
        ("solutions/ is empty", f"ls -A {ROOT / 'solutions'} | wc -l", "0"),
        ("the classmate's folder is empty", f"ls -A {classmate} | wc -l", "0"),
        ("the kit is readable", f"test -r {ROOT / 'README.md'} && echo yes", "yes"),
        ("the kit is read-only", f"touch {ROOT / 'pwned'} 2>/dev/null && echo written || echo refused", "refused"),
        ("the root is read-only", "touch /pwned 2>/dev/null && echo written || echo refused", "refused"),
        ("the tree is read-only for a test", f"touch {tree / 'x'} 2>/dev/null && echo written || echo refused", "refused"),
        ("no secret in the environment", "env | grep -c KIT_TEST_SECRET", "0"),
        ("no network: loopback only", "grep -c : /proc/net/dev", "1"),
        ("a private, writable /tmp", "touch /tmp/kit-sandbox-scratch && echo written", "written"),
    ]
    if (ROOT / ".git").exists():
        checks.append(("the kit's history is hidden", f"ls -A {ROOT / '.git'} 2>/dev/null | wc -l", "0"))
    home = os.environ.get("HOME")
    if home and pathlib.Path(home).is_dir() and not str(ROOT).startswith(home.rstrip("/") + "/"):
        checks.append(("the grader's home is empty", f"ls -A {home} | wc -l", "0"))
    problems = []
    for what, script, want in checks:
        _, got = inside(script)
        print(f"{'ok  ' if got == want else 'FAIL'} {what}: {got!r}")
        if got != want:
            problems.append(what)
    _, got = inside(f"touch {tree / 'built'} && echo written", writable=True)
    if got != "written" or not (tree / "built").exists():
        problems.append("the tree is not writable for a build")
    if pathlib.Path("/tmp/kit-sandbox-scratch").exists():
        problems.append("the sandbox's /tmp is the machine's")
    if (ROOT / "pwned").exists() or (classmate / "rk4.hpp").read_text() != "a classmate's work\n":
        problems.append("something outside the tree changed")
    print(f"{len(checks) + 1} checks; {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
