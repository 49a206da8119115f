#!/usr/bin/env python3
"""The grader's program cache (tools/grading/program_cache.py) keeps what it should, gives back
what it kept, and forgets what it must:

  - an entry stored by one batch is fetched whole by the next (the program, its compile log and
    the disk it is charged), and a second store of the same key keeps the first;
  - a key never stored, or one trimmed away, is a miss that leaves nothing behind;
  - a trim keeps the folder within its bound by removing the entries used least recently: one
    fetched since it was stored outlives an older one that was not;
  - only compiles that always end the same way are kept: a program or a compiler error, not a
    compile stopped by the wall clock, a signal (bwrap's 128 + n, the driver's message, a
    negative code) or a full disk;
  - two processes claiming one key take turns, so two batches at once compile a file once;
  - a --cache that cannot be a folder, or a negative --cache-mib, is refused (exit 2, naming it)
    before the batch writes anything.

Usage: grade_program_cache.py WORK_DIR
"""
import multiprocessing
import os
import pathlib
import shutil
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
from grading.program_cache import ProgramCache, repeatable  # noqa: E402


def entry(folder, program_bytes, log="", used=None):
    """A batch's finished entry: `program_bytes` of program (None: it did not build)."""
    folder.mkdir(parents=True)
    if program_bytes is not None:
        (folder / "program").write_bytes(b"\x7fELF" + b"x" * program_bytes)
    (folder / "compile.log").write_text(log)
    (folder / "used").write_text(str(used if used is not None else program_bytes or 0))
    return folder


def hold(folder, key, marker):
    """Claims `key`, leaves a marker, holds the claim a moment, and writes that it let go."""
    cache = ProgramCache(folder, 1 << 20)
    with cache.claim(key):
        (folder / f"{marker}.held").touch()
        time.sleep(0.5)
        (folder / f"{marker}.released").touch()


def main(argv):
    work = pathlib.Path(argv[1]).resolve()
    shutil.rmtree(work, ignore_errors=True)
    folder, batch = work / "cache", work / "batch"
    batch.mkdir(parents=True)
    problems = []

    # Stored by one batch, fetched whole by the next; the first store of a key stays.
    cache = ProgramCache(folder, 1 << 20)
    cache.store("a", entry(work / "made-a", 1000, "a warning", used=1234))
    cache.store("a", entry(work / "made-a2", 10, "another compile"))
    if not cache.fetch("a", batch / "a"):
        problems.append("a stored entry was not fetched")
    elif ((batch / "a" / "program").read_bytes() != (work / "made-a" / "program").read_bytes()
          or (batch / "a" / "compile.log").read_text() != "a warning" or (batch / "a" / "used").read_text() != "1234"):
        problems.append("the fetched entry is not the first one stored, whole")
    cache.store("b", entry(work / "made-b", None, "b.hpp:3:1: error: expected ';'", used=0))
    if not cache.fetch("b", batch / "b") or (batch / "b" / "program").exists() \
            or "error" not in (batch / "b" / "compile.log").read_text():
        problems.append("a compiler error was not given back as one (its log, no program)")
    if cache.fetch("never", batch / "never") or (batch / "never").exists():
        problems.append("a key never stored was a hit, or left a folder behind")
    if (cache.hits, cache.stores) != (2, 2):
        problems.append(f"expected 2 hits and 2 stores, counted {cache.hits} and {cache.stores}")

    # Least recently used first: c was used before b, but fetched since; a is the newest of all.
    cache.store("c", entry(work / "made-c", 1000))
    now = time.time()
    for key, age in (("a", 100), ("b", 300), ("c", 350)):
        os.utime(folder / key, (now - age, now - age))
    if not cache.fetch("c", batch / "c-again"):
        problems.append("c was not fetched")
    size = {k: sum(p.stat().st_size for p in (folder / k).iterdir()) for k in "abc"}
    small = ProgramCache(folder, size["a"] + size["c"])
    kept, removed = small.trim()
    left = sorted(p.name for p in folder.iterdir() if not p.name.startswith("."))
    if left != ["a", "c"] or removed != 1 or kept != size["a"] + size["c"]:
        problems.append(f"a trim to {size['a'] + size['c']} bytes should remove b (used least recently) alone; "
                        f"it left {left}, {kept} bytes, {removed} removed")
    if small.fetch("b", batch / "b-trimmed") or (batch / "b-trimmed").exists():
        problems.append("a trimmed entry was still fetched, or its fetch left a folder behind")
    ProgramCache(folder, size["c"]).trim()  # a goes now: the entry a batch fetched before
    if small.fetch("a", batch / "a-trimmed") or (batch / "a-trimmed").exists():
        problems.append("a trimmed entry was still fetched, or its fetch left a folder behind")
    if not (batch / "a" / "program").is_file() or (batch / "a" / "program").read_bytes()[:4] != b"\x7fELF":
        problems.append("a trim took the program from a batch that had fetched it")
    ProgramCache(folder, 0).trim()
    if any(not p.name.startswith(".") for p in folder.iterdir()):
        problems.append("a trim to 0 bytes left entries")

    # Kept: outcomes every compile of the file has. Not kept: a limit of time or of the machine.
    for code, log, want in ((0, "", True), (1, "rk4.hpp:3:5: error: 'x' was not declared", True),
                            (1, "ld: final link failed: File too large", True), (None, "", False),
                            (128 + 9, "", False), (128 + 24, "", False), (-9, "", False),
                            (1, "c++: fatal error: Killed signal terminated program cc1plus", False),
                            (1, "CPU time limit exceeded signal terminated program cc1plus", False),
                            (1, "error: No space left on device", False)):
        if repeatable(code, log) != want:
            problems.append(f"a compile ending {code} with {log!r} should {'' if want else 'not '}be kept")

    # Two processes claiming one key take turns.
    turns = work / "turns"
    turns.mkdir()
    first = multiprocessing.Process(target=hold, args=(turns, "k", "first"))
    first.start()
    while not (turns / "first.held").exists() and first.is_alive():
        time.sleep(0.01)
    second = multiprocessing.Process(target=hold, args=(turns, "k", "second"))
    second.start()
    first.join(), second.join()
    if not (turns / "first.released").exists() or not (turns / "second.held").exists():
        problems.append("the claims did not both finish")
    elif (turns / "second.held").stat().st_mtime_ns < (turns / "first.released").stat().st_mtime_ns:
        problems.append("the second process held the key while the first still did")

    # A --cache that cannot be a folder is refused before anything is written: exit 2, naming it.
    not_a_folder = work / "a-file"
    not_a_folder.write_text("x")
    for flags, named in ((["--cache", str(not_a_folder)], f"--cache {not_a_folder}"),
                         (["--cache", str(work / "c"), "--cache-mib", "-1"], "--cache-mib -1")):
        refused = subprocess.run([sys.executable, str(ROOT / "tools/grade.py"), "batch", "--out", str(work / "out"),
                                  "--judges", str(work), "--common-library", str(not_a_folder), "--no-sandbox",
                                  *flags, str(ROOT / "exercises")], capture_output=True, text=True)
        if refused.returncode != 2 or named not in refused.stderr or (work / "out").exists():
            problems.append(f"grade.py {' '.join(flags)}: exit {refused.returncode}, expected 2 naming {named} and "
                            f"no --out folder: {refused.stderr.strip()[:300]}")

    for p in problems:
        print(p, file=sys.stderr)
    print(f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
