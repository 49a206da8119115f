#!/usr/bin/env python3
"""The grader's sandbox hides what it promises to hide, whatever the student code does with it,
and its limits stop a fork bomb and an endless loop.

Runs commands through grading.sandbox exactly as the grader does (Sandbox.confined: a compile
sees its folder writable, a run sees its program's folder read-only), and checks from inside:
only the system folders and the given folder are there (no /home, /root, /var, /etc/passwd or
/etc/shadow); of the kit only the confinement script, so no solutions/, .git or test source;
another submission is invisible, the system is read-only, no capability is left to mount
anything, the environment holds no secret, there is no network, a run has nowhere to write,
and a compile only its own folder; a folder shared with every compile (the harness, the
precompiled header) is readable and never writable.
Then, under a graded test's limits: a fork bomb in a static initialiser is killed at its first
fork and a busy loop at its CPU seconds; a compiler still builds a program under the build's
limits, and that program runs under a test's.

Usage: sandbox_hides.py WORK_DIR
"""
import os
import pathlib
import shutil
import signal
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
from grading.sandbox import BUILD_LIMITS, TEST_MEMORY, Limits, Sandbox, test_limits  # noqa: E402


# A program with a bounded fork bomb in a static initialiser (bounded, so that a sandbox without
# the limit does not hurt the machine running this test): it forks when BOMB is set.
PROGRAM = r"""#include <unistd.h>
#include <cstdio>
#include <cstdlib>
static const int forked = [] {
  int n = 0;
  for (; std::getenv("BOMB") && n < 200; ++n) {
    const pid_t pid = fork();
    if (pid == 0) { sleep(5); _exit(0); }
    if (pid < 0) break;
  }
  return n;
}();
int main() { std::printf("forked %d\n", forked); }
"""


def check_limits(sandbox, tree, inside):
    """A compiler works under the build's limits; under a graded test's, the program it built runs,
    its fork bomb dies at the first fork, and a busy loop at its CPU seconds."""
    problems = []

    def timed(what, run, want_code, want_output, within):
        start = time.monotonic()
        try:
            code, output = run()
        except subprocess.TimeoutExpired:
            code, output = "no end", ""
        seconds = time.monotonic() - start
        good = code == want_code and output == want_output and seconds < within
        print(f"{'ok  ' if good else 'FAIL'} {what}: exit {code}, {output!r}, {seconds:.1f} s")
        if not good:
            problems.append(what)

    def run_program(env, limits):
        command = sandbox.confined([str(tree / "prog")], [tree], [], limits, env=env)
        done = subprocess.run(command, capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=30)
        return done.returncode, done.stdout.strip()

    (tree / "prog.cpp").write_text(PROGRAM)
    timed("g++ builds a program under the build's limits",
          lambda: inside("g++ -O1 -o prog prog.cpp && echo built", writable=True, limits=BUILD_LIMITS),
          0, "built", 120)
    timed("the program runs under a graded test's limits", lambda: run_program({}, test_limits(10)),
          0, "forked 0", 10)
    # bwrap reports a child killed by a signal as 128 + the signal: SIGSYS from the filter, SIGXCPU.
    timed("a fork bomb in a static initialiser dies at once", lambda: run_program({"BOMB": "1"}, test_limits(10)),
          128 + signal.SIGSYS, "", 5)
    timed("a busy loop dies at its CPU seconds",
          lambda: inside("while :; do :; done", limits=test_limits(2), timeout=30),
          128 + signal.SIGXCPU, "", 15)
    return problems


def main(argv):
    work = pathlib.Path(argv[1]).resolve()
    shutil.rmtree(work, ignore_errors=True)
    tree, classmate = work / "out" / "me", work / "class" / "classmate"
    tree.mkdir(parents=True)
    classmate.mkdir(parents=True)
    (classmate / "rk4.hpp").write_text("a classmate's work\n")
    os.environ["KIT_TEST_SECRET"] = "do-not-leak"
    sandbox = Sandbox()

    # The hiding checks need a shell that starts processes (pipes), which a graded test may not.
    shell_limits = Limits(TEST_MEMORY, 60, True)

    def inside(script, writable=False, limits=shell_limits, timeout=60):
        command = sandbox.confined(["sh", "-c", script], [] if writable else [tree], [tree] if writable else [], limits,
                                   cwd=tree)
        done = subprocess.run(command, capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=timeout)
        return done.returncode, done.stdout.strip()

    # At the top: the system's folders (and links) as this machine has them, the way to the tree and
    # the way to the confinement script (tools/grading/confine.py, bound alone), nothing else.
    top = {n for n in ("bin", "sbin", "lib", "lib32", "lib64", "libx32") if os.path.lexists(f"/{n}")}
    top |= {"usr", "etc", "dev", "proc", ROOT.parts[1], tree.parts[1]}  # no /tmp
    hidden_tops = [f"/{d}" for d in ("home", "root", "var", "run", "srv", "opt", "mnt", "media", "boot")
                   if d not in (ROOT.parts[1], tree.parts[1])]
    checks = [
        ("of the kit only the confinement script", f"find {ROOT} -type f | tr '\\n' ' '",
         str(ROOT / "tools" / "grading" / "confine.py")),
        ("no solutions/", f"ls -A {ROOT / 'solutions'} 2>/dev/null | wc -l", "0"),
        ("no test source", f"ls {ROOT / 'tests' / 'grading'} 2>/dev/null | wc -l", "0"),
        ("the classmate's folder is not there", f"ls -A {classmate} 2>/dev/null | wc -l", "0"),
        ("the root is read-only", "touch /pwned 2>/dev/null && echo written || echo refused", "refused"),
        ("the folder is read-only for a run", f"touch {tree / 'x'} 2>/dev/null && echo written || echo refused", "refused"),
        ("no secret in the environment", "env | grep -c KIT_TEST_SECRET", "0"),
        ("no network: loopback only", "grep -c : /proc/net/dev", "1"),
        ("nowhere to write for a run", "for d in /tmp /dev /dev/shm / $HOME; do touch $d/kit-x 2>/dev/null && echo $d; "
         "done | wc -l", "0"),
        ("only the system and the two ways at the top", "ls -A / | sort | tr '\\n' ' '", " ".join(sorted(top))),
        (f"no {', '.join(hidden_tops)}", f"ls -d {' '.join(hidden_tops)} 2>/dev/null | wc -l", "0"),
        ("no /etc/passwd, /etc/shadow, /etc/hostname", "cat /etc/passwd /etc/shadow /etc/hostname 2>/dev/null | wc -c",
         "0"),
        ("in /etc only the loader's files and the alternatives", "ls -A /etc | grep -cv '^ld\\.so\\.\\|^alternatives$'",
         "0"),
        ("no capability left", "grep CapEff /proc/self/status | tr -d '\\t'", "CapEff:0000000000000000"),
        ("nothing can be mounted", f"mount -t tmpfs none {tree} 2>/dev/null && echo mounted || echo refused", "refused"),
        ("a compiler is there", "for c in c++ g++ python3; do command -v $c; done | wc -l", "3"),
    ]
    home = os.environ.get("HOME")
    if home and pathlib.Path(home).is_dir() and not str(ROOT).startswith(home.rstrip("/") + "/"):
        checks.append(("the grader's home is not there", f"ls -A {home} 2>/dev/null | wc -l", "0"))
    problems = []
    for what, script, want in checks:
        _, got = inside(script)
        print(f"{'ok  ' if got == want else 'FAIL'} {what}: {got!r}")
        if got != want:
            problems.append(what)
    _, got = inside(f"touch {tree / 'built'} && echo written", writable=True)
    if got != "written" or not (tree / "built").exists():
        problems.append("a compile's folder is not writable")
    _, got = inside("touch /tmp/kit-sandbox-scratch 2>/dev/null && echo written || echo refused", writable=True)
    if got != "refused" or pathlib.Path("/tmp/kit-sandbox-scratch").exists():
        problems.append("a compile can write outside its folder (/tmp)")
    if (ROOT / "pwned").exists() or (classmate / "rk4.hpp").read_text() != "a classmate's work\n":
        problems.append("something outside the folder changed")
    # What every compile of the batch reads (the harness, the precompiled header): readable, never
    # writable, not even by a compile, whose student could otherwise plant code in the others'.
    shared = work / "out" / ".grading-shared" / "harness"
    shared.mkdir(parents=True)
    (shared / "student_pch.hpp").write_text("the batch's header\n")
    command = sandbox.confined(["sh", "-c", f"cat {shared / 'student_pch.hpp'}; (echo x >> {shared / 'student_pch.hpp'} "
                                f"|| touch {shared / 'planted'}) 2>/dev/null && echo written || echo refused"],
                               [shared], [tree], shell_limits)
    got = subprocess.run(command, capture_output=True, text=True, stdin=subprocess.DEVNULL, timeout=60).stdout.split()
    if got[-1:] != ["refused"] or "header" not in got or (shared / "student_pch.hpp").read_text() != "the batch's header\n":
        problems.append(f"a compile can write into what the batch shares, or cannot read it: {got}")
    problems += check_limits(sandbox, tree, inside)
    print(f"{len(checks) + 6} checks; {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
