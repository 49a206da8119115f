"""Students' compiled programs kept from one sandboxed batch to the next.

A regrade, a late submission added to a class, or a classmate's identical file then costs no
compile. An entry is keyed by everything a compile reads (tools/grade.py: the compiler, its
flags and limits, the preprocessed system headers, the kit's files the exercise may see, the
student's file), so a hit is the program that compile would make again.

Why it can be trusted:
  - only the grader writes here, and only what a compile in the sandbox produced; the sandbox
    shows no student's code this folder (it is under the kit's build, which bwrap does not bind);
  - a batch without the sandbox neither reads nor writes it: there a student's program runs
    with the grader's rights and could rewrite it for the next class;
  - only outcomes that the same file always has are kept: a program, or a compiler error. A
    compile stopped by a limit of time or of the machine (a signal, the wall clock, a full disk)
    is kept for its batch alone, and tried again by the next;
  - an entry appears whole (a folder renamed into place) or not at all; a batch takes a hard
    link or a copy of it, so that a later batch's trim never pulls a program from under a run.

The folder holds at most `limit` bytes after each batch: the entries used least recently go
first."""
import contextlib
import fcntl
import os
import pathlib
import shutil
import tempfile
import time

ENTRY_FILES = ("program", "compile.log", "used")
# Part of every key (tools/grade.py): change it with what an entry holds, and old entries go unused.
FORMAT = "entry 1: program, the whole compile log, used bytes"


def repeatable(code, log):
    """Whether a compile that ended with exit code `code` (None: stopped by the wall clock) and
    wrote `log` would end the same way every time: it built, or the compiler refused the file. Not
    so when a limit of time or of the machine stopped it: a signal (bwrap reports 128 + the signal;
    the compiler driver, a child's), or a full disk."""
    if code is None or code < 0 or code >= 128:
        return False
    return "signal terminated program" not in log and "No space left on device" not in log


def _size(folder):
    return sum(p.stat().st_size for p in folder.iterdir() if p.is_file())


class ProgramCache:
    def __init__(self, folder, limit):
        self.folder, self.limit = pathlib.Path(folder), limit
        self.locks = self.folder / ".locks"
        self.locks.mkdir(parents=True, exist_ok=True)
        self.hits = self.stores = 0

    @contextlib.contextmanager
    def claim(self, key):
        """Held while one process looks up and compiles `key`: two batches at once (two
        instructors, or the kit's tests) compile a file once between them."""
        with open(self.locks / key, "a") as handle:
            fcntl.flock(handle, fcntl.LOCK_EX)
            try:
                yield
            finally:
                fcntl.flock(handle, fcntl.LOCK_UN)

    def fetch(self, key, entry):
        """Fills the batch's `entry` folder from the cache. Returns whether it did; on any
        failure (an entry trimmed meanwhile, say) `entry` is left absent: the caller compiles."""
        source = self.folder / key
        if not source.is_dir():
            return False
        try:
            entry.mkdir()
            for name in ENTRY_FILES:
                if (source / name).is_file():
                    try:
                        os.link(source / name, entry / name)
                    except OSError:  # another file system, or no hard links there
                        shutil.copy2(source / name, entry / name)
            if not (entry / "used").is_file():
                raise FileNotFoundError(source / "used")
            os.utime(source)  # used now: trimmed last
        except OSError:
            shutil.rmtree(entry, ignore_errors=True)
            return False
        self.hits += 1
        return True

    def store(self, key, entry):
        """Keeps a copy of the batch's finished `entry` under `key`, unless one is there."""
        if (self.folder / key).exists():
            return
        staging = pathlib.Path(tempfile.mkdtemp(prefix=".new-", dir=self.folder))
        try:
            for name in ENTRY_FILES:
                if (entry / name).is_file():
                    shutil.copy2(entry / name, staging / name)
            os.rename(staging, self.folder / key)  # whole or not at all
            self.stores += 1
        except OSError:  # another batch stored it first, or the disk is full: the cache is optional
            shutil.rmtree(staging, ignore_errors=True)

    def trim(self):
        """Removes the entries used least recently until the folder holds at most `limit` bytes.
        Returns (bytes kept, entries removed)."""
        with open(self.locks / ".trim", "a") as handle:
            fcntl.flock(handle, fcntl.LOCK_EX)
            entries = []
            for path in self.folder.iterdir():
                if path.name.startswith("."):
                    continue
                try:
                    entries.append((path.stat().st_mtime, _size(path), path))
                except OSError:
                    continue
            total, removed = sum(size for _, size, _ in entries), 0
            for _, size, path in sorted(entries, key=lambda e: (e[0], e[2].name)):
                if total <= self.limit:
                    break
                doomed = self.folder / f".old-{path.name}"
                try:
                    os.rename(path, doomed)  # gone at once for any batch looking it up
                except OSError:
                    continue
                shutil.rmtree(doomed, ignore_errors=True)
                with contextlib.suppress(OSError):
                    (self.locks / path.name).unlink()
                total, removed = total - size, removed + 1
            for stale in self.folder.glob(".new-*"):  # left by a batch killed while storing
                with contextlib.suppress(OSError):
                    if stale.stat().st_mtime < time.time() - 3600:
                        shutil.rmtree(stale, ignore_errors=True)
            return total, removed
