"""The sandbox every process that reads or runs student code goes through (bubblewrap).

  - the whole file system is read-only;
  - the kit's solutions/ and .git, every other submission, the grade trees of the batch and the
    kit's own build folder are hidden (empty in the sandbox);
  - the submission's own grade tree is visible: writable for the build, read-only for the tests;
  - a private /tmp, no network, no other process visible (new namespaces), and the process dies
    with the grader;
  - a limit on address space (memory) and on CPU time, and the grader's wall-clock timeout.
Without bubblewrap (or with --no-sandbox) commands run bare, with the same limits, and every
report says so."""
import pathlib
import shutil
import subprocess

BUILD_MEMORY = 4 << 30   # bytes of address space for a compiler process
TEST_MEMORY = 2 << 30    # bytes of address space for a graded test


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
        args = []
        for path in [self.kit_root / "solutions", self.kit_root / ".git", *self.hidden]:
            if path.exists():
                args += ["--tmpfs", str(path)]
        return args

    def wrap(self, command, tree, writable, memory):
        """`command` confined to `tree` (a grade tree), with `memory` bytes of address space."""
        limits = ["prlimit", f"--as={memory}", "--"]
        if not self.enabled:
            return limits + command
        bind = "--bind" if writable else "--ro-bind"
        return (["bwrap", "--ro-bind", "/", "/", "--dev", "/dev", "--proc", "/proc", "--tmpfs", "/tmp",
                 "--unshare-all", "--die-with-parent", "--new-session"]
                + self._hide() + [bind, str(tree), str(tree), "--chdir", str(tree), "--setenv", "HOME", "/tmp",
                                  "--setenv", "TMPDIR", "/tmp", "--unsetenv", "CCACHE_DIR", "--setenv",
                                  "CCACHE_DISABLE", "1", "--"] + limits + command)
