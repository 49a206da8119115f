"""The sandbox every process that reads or runs student code goes through (bubblewrap).

  - nothing of the machine's file system but what the tools need, read-only: /usr, the /bin,
    /sbin, /lib* links (or folders) as the machine has them, the dynamic loader's cache and the
    alternatives links of /etc; the kit itself, read-only; and the submission's own grade tree,
    writable for the build and read-only for the tests. No /home, /root, /var, /etc/passwd…;
  - in the kit, solutions/ and .git, every other submission, the grade trees of the batch and the
    kit's own build folder are hidden (empty in the sandbox);
  - a private /tmp for a build, and no writable place at all for a test (/dev is read-only);
    no network, no other process visible (new namespaces), no capabilities (so no mount can be
    undone, even when the grader runs as root), an empty environment (PATH, HOME=/tmp and the
    evidence descriptor only), no stdin, and the process dies with the grader;
  - limits (grading/confine.py, the last step before the command): address space, the size of
    any file written, CPU seconds per process and no core dump; a graded test may not start a
    process or a thread (a seccomp filter kills it on fork/clone); plus the grader's wall-clock
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
    def __init__(self, kit_root, hidden, enabled=True):
        self.kit_root = pathlib.Path(kit_root)
        self.hidden = [pathlib.Path(p) for p in hidden]
        self.shared = []  # folders every sandboxed command may read (the batch's precompiled header)
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
        probe = subprocess.run(self.wrap(["true"], self.kit_root, False, test_limits(10)),
                               capture_output=True, text=True, stdin=subprocess.DEVNULL)
        if probe.returncode != 0:
            raise SandboxUnavailable(f"cannot limit a graded test here: {probe.stdout.strip()[:300]}"
                                     f"{probe.stderr.strip()[:300]}")

    def _kit(self):
        """The kit, read-only, with its secrets hidden: solutions/, .git, and every hidden path
        that lies inside it (other submissions, grade trees, the build folder)."""
        args = ["--ro-bind", str(self.kit_root), str(self.kit_root)]
        git = subprocess.run(["git", "-C", str(self.kit_root), "rev-parse", "--git-common-dir"],
                             capture_output=True, text=True)
        secrets = [self.kit_root / "solutions", self.kit_root / ".git", *self.hidden]
        if git.returncode == 0 and git.stdout.strip():
            secrets.append((self.kit_root / git.stdout.strip()).resolve())
        root = self.kit_root.resolve()
        for path in secrets:
            if not path.resolve().is_relative_to(root):
                continue  # outside the kit: not in the sandbox at all
            if path.is_dir():
                args += ["--tmpfs", str(path)]
            elif path.exists():
                args += ["--ro-bind", "/dev/null", str(path)]  # a .git file (worktree), say
        return args

    def share(self, folder):
        """Makes `folder` readable, never writable, by every command wrapped from now on."""
        self.shared.append(pathlib.Path(folder))

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

    def wrap(self, command, tree, writable, limits, env=None):
        """`command` confined to `tree` (a grade tree) under `limits`, with `env` as the only
        variables it gets besides PATH, HOME, TMPDIR and LANG."""
        extra = [word for key, value in sorted((env or {}).items()) for word in ("--setenv", key, value)]
        confine = [PYTHON, "-I", "-S", str(CONFINE), "--as", str(limits.memory), "--fsize", str(OUTPUT_LIMIT),
                   "--cpu", str(limits.cpu), *([] if limits.spawn else ["--no-spawn"]), "--"]
        if not self.enabled:
            return ["env", *[f"{k}={v}" for k, v in sorted((env or {}).items())]] + confine + command
        # A build gets a private /tmp (the compiler's scratch files); a test, no writable place at
        # all, so that it cannot fill the machine's memory with files in a tmpfs.
        bind, scratch = (["--bind"], ["--tmpfs", "/tmp"]) if writable else (["--ro-bind"], [])
        return (["bwrap", *system_binds(), "--dev", "/dev", "--remount-ro", "/dev", "--proc", "/proc", *scratch,
                 "--unshare-all", "--die-with-parent", "--new-session", "--cap-drop", "ALL", "--clearenv",
                 "--setenv", "PATH", "/usr/local/bin:/usr/bin:/bin", "--setenv", "HOME", "/tmp",
                 "--setenv", "TMPDIR", "/tmp", "--setenv", "LANG", "C.UTF-8", "--setenv", "CCACHE_DISABLE", "1"]
                + extra + self._kit() + [word for f in self.shared for word in ("--ro-bind", str(f), str(f))]
                + [*bind, str(tree), str(tree), "--remount-ro", "/", "--chdir", str(tree), "--"]
                + confine + command)
