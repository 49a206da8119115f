"""The sandbox every process that compiles or runs student code goes through (bubblewrap).

  - nothing of the machine's file system but what the tools need, read-only: /usr, the /bin,
    /sbin, /lib* links (or folders) as the machine has them, the dynamic loader's cache and the
    alternatives links of /etc; then only the folders the step names (Sandbox.confined): for a
    compile, the one student file, the exercise's allowed headers and objects, the harness and
    the batch's precompiled header, read-only, and its own scratch folder, writable; for a run,
    the program, read-only. Nothing of the kit but the confinement script, no other submission,
    no /home, /root, /var, /etc/passwd…;
  - no writable place at all for a run (/dev is read-only); no network, no other process visible
    (new namespaces), no capabilities (so no mount can be made or undone, even when the grader
    runs as root), an empty environment (PATH, HOME, LANG and what the step passes), no stdin,
    and the process dies with the grader;
  - limits (grading/confine.py, the last step before the command): address space, the size of
    any file written, CPU seconds per process and no core dump; a student's program may not start
    a process or a thread (a seccomp filter kills it on fork/clone); plus the grader's wall-clock
    timeout.
Without bubblewrap (or with --no-sandbox) commands run bare, with the same limits, and every
report says so."""
import math
import os
import pathlib
import shutil
import subprocess
import sys
from typing import NamedTuple

BUILD_MEMORY = 4 << 30   # bytes of address space for a compiler process
TEST_MEMORY = 2 << 30    # bytes of address space for a graded test
OUTPUT_LIMIT = 1 << 30   # bytes a process may write to any one file (build tree, output, evidence)
BUILD_CPU = 900          # CPU seconds for one compiler process (a heavy Eigen file takes under 60)

CONFINE = pathlib.Path(__file__).resolve().parent / "confine.py"
# The machine's own Python (the grader may run under another one, in a folder the sandbox hides).
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else (shutil.which("python3") or sys.executable)

# What the compiler, cmake, ninja, Python and the test programs need of the machine, read-only.
SYSTEM_DIRS = ["/usr"]
SYSTEM_TOP_LEVEL = ["/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"]  # links into /usr, or folders
SYSTEM_ETC = ["/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/alternatives"]


class Limits(NamedTuple):
    memory: int   # bytes of address space
    cpu: int      # CPU seconds per process
    spawn: bool   # may start processes and threads


BUILD_LIMITS = Limits(BUILD_MEMORY, BUILD_CPU, True)


def test_limits(timeout):
    """A graded test: 2 GiB, as many CPU seconds as the wall-clock timeout, no new process."""
    return Limits(TEST_MEMORY, max(1, math.ceil(timeout)), False)


class SandboxUnavailable(Exception):
    pass


def system_binds():
    """bwrap arguments for the machine's read-only part, as it exists here."""
    args = []
    for path in SYSTEM_DIRS:
        args += ["--ro-bind", path, path]
    for path in SYSTEM_TOP_LEVEL:
        if os.path.islink(path):
            args += ["--symlink", os.readlink(path), path]
        elif os.path.isdir(path):
            args += ["--ro-bind", path, path]
    for path in SYSTEM_ETC:
        args += ["--ro-bind-try", path, path]
    return args


class Sandbox:
    def __init__(self, enabled=True):
        self.enabled = enabled
        if enabled:
            self._probe()
        self._probe_limits()

    def _probe(self):
        bwrap = shutil.which("bwrap")
        if not bwrap:
            raise SandboxUnavailable("bubblewrap (bwrap) is not installed: `./kit deps --for grade` installs it")
        probe = subprocess.run([bwrap, *system_binds(), "--dev", "/dev", "--proc", "/proc", "--unshare-all",
                                "--cap-drop", "ALL", "--die-with-parent", "true"], capture_output=True, text=True)
        if probe.returncode != 0:
            raise SandboxUnavailable(f"bwrap cannot create a sandbox here: {probe.stderr.strip()[:300]}")

    def _probe_limits(self):
        """The limits a graded test gets can be set here (the seccomp filter knows this machine)."""
        probe = subprocess.run(self.confined(["true"], [], [], test_limits(10)),
                               capture_output=True, text=True, stdin=subprocess.DEVNULL)
        if probe.returncode != 0:
            raise SandboxUnavailable(f"cannot limit a graded test here: {probe.stdout.strip()[:300]}"
                                     f"{probe.stderr.strip()[:300]}")

    def confined(self, command, readable, writable, limits, env=None, cwd=None, fsize=OUTPUT_LIMIT):
        """`command` seeing the machine's read-only part, the folders `readable` (read-only) and
        `writable`, and nothing of the kit: a student's compile (its file, the headers its
        exercise may use, the harness) and a student's program (the program alone). TMPDIR is the
        first writable folder, or unset (no writable place at all)."""
        env = dict(env or {})
        if writable:
            env.setdefault("TMPDIR", str(writable[0]))
        confine = [PYTHON, "-I", "-S", str(CONFINE), "--as", str(limits.memory), "--fsize", str(fsize),
                   "--cpu", str(limits.cpu), *([] if limits.spawn else ["--no-spawn"]), "--"]
        if not self.enabled:
            return ["env", *[f"{k}={v}" for k, v in sorted(env.items())]] + confine + command
        extra = [word for key, value in sorted(env.items()) for word in ("--setenv", key, value)]
        binds = [word for f in readable for word in ("--ro-bind", str(f), str(f))]
        binds += [word for f in writable for word in ("--bind", str(f), str(f))]
        return (["bwrap", *system_binds(), "--dev", "/dev", "--remount-ro", "/dev", "--proc", "/proc",
                 "--unshare-all", "--die-with-parent", "--new-session", "--cap-drop", "ALL", "--clearenv",
                 "--setenv", "PATH", "/usr/local/bin:/usr/bin:/bin", "--setenv", "HOME", "/nonexistent",
                 "--setenv", "LANG", "C.UTF-8", "--setenv", "CCACHE_DISABLE", "1"] + extra
                + ["--ro-bind", str(CONFINE), str(CONFINE)] + binds
                + ["--remount-ro", "/", "--chdir", str(cwd or (writable or readable or ["/"])[0]), "--"]
                + confine + command)
