"""The sandbox every process that reads or runs student code goes through (bubblewrap).

  - the whole file system is read-only;
  - the kit's solutions/ and .git, every other submission, the grade trees of the batch and the
    kit's own build folder are hidden (empty in the sandbox);
  - the submission's own grade tree is visible: writable for the build, read-only for the tests;
  - a private /tmp, no network, no other process visible (new namespaces), the grader's home
    hidden, an empty environment (PATH, HOME=/tmp and the evidence descriptor only), no stdin,
    and the process dies with the grader;
  - limits on address space (memory) and on the size of any file written, and the grader's
    wall-clock timeout.
Without bubblewrap (or with --no-sandbox) commands run bare, with the same limits, and every
report says so."""
import os
import pathlib
import shutil
import subprocess

BUILD_MEMORY = 4 << 30   # bytes of address space for a compiler process
TEST_MEMORY = 2 << 30    # bytes of address space for a graded test
OUTPUT_LIMIT = 1 << 30   # bytes a process may write to any one file (build tree, output, evidence)


class SandboxUnavailable(Exception):
    pass


class Sandbox:
    def __init__(self, kit_root, hidden, enabled=True):
        self.kit_root = pathlib.Path(kit_root)
        self.hidden = [pathlib.Path(p) for p in hidden]
        self.enabled = enabled
        if enabled:
            self._probe()

    def _probe(self):
        bwrap = shutil.which("bwrap")
        if not bwrap:
            raise SandboxUnavailable("bubblewrap (bwrap) is not installed: `./kit deps --for grade` installs it")
        probe = subprocess.run([bwrap, "--ro-bind", "/", "/", "--dev", "/dev", "--proc", "/proc", "--unshare-all",
                                "--die-with-parent", "true"], capture_output=True, text=True)
        if probe.returncode != 0:
            raise SandboxUnavailable(f"bwrap cannot create a sandbox here: {probe.stderr.strip()[:300]}")

    def _hide(self):
        """Mounts that hide: the grader's home and every secret path; the kit is bound again first,
        so a kit that lives under /tmp or the home folder stays visible (read-only)."""
        args = []
        home = os.environ.get("HOME")
        if home and pathlib.Path(home).is_dir() and pathlib.Path(home) != pathlib.Path("/"):
            args += ["--tmpfs", home]
        args += ["--ro-bind", str(self.kit_root), str(self.kit_root)]
        git = subprocess.run(["git", "-C", str(self.kit_root), "rev-parse", "--git-common-dir"],
                             capture_output=True, text=True)
        secrets = [self.kit_root / "solutions", self.kit_root / ".git", *self.hidden]
        if git.returncode == 0 and git.stdout.strip():
            secrets.append((self.kit_root / git.stdout.strip()).resolve())
        for path in secrets:
            if path.is_dir():
                args += ["--tmpfs", str(path)]
            elif path.exists():
                args += ["--ro-bind", "/dev/null", str(path)]  # a .git file (worktree), say
        return args

    def wrap(self, command, tree, writable, memory, env=None):
        """`command` confined to `tree` (a grade tree), with `memory` bytes of address space, and
        `env` as the only variables it gets besides PATH, HOME, TMPDIR and LANG."""
        extra = [word for key, value in sorted((env or {}).items()) for word in ("--setenv", key, value)]
        limits = ["prlimit", f"--as={memory}", f"--fsize={OUTPUT_LIMIT}", "--"]
        if not self.enabled:
            return ["env", *[f"{k}={v}" for k, v in sorted((env or {}).items())]] + limits + command
        bind = "--bind" if writable else "--ro-bind"
        return (["bwrap", "--ro-bind", "/", "/", "--dev", "/dev", "--proc", "/proc", "--tmpfs", "/tmp",
                 "--unshare-all", "--die-with-parent", "--new-session", "--clearenv",
                 "--setenv", "PATH", "/usr/local/bin:/usr/bin:/bin", "--setenv", "HOME", "/tmp",
                 "--setenv", "TMPDIR", "/tmp", "--setenv", "LANG", "C.UTF-8", "--setenv", "CCACHE_DISABLE", "1"]
                + extra + self._hide() + [bind, str(tree), str(tree), "--chdir", str(tree), "--"] + limits + command)

