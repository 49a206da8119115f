#!/usr/bin/env python3
"""The kit's C++ is formatted as .clang-format says, by clang-format 14 (Debian 12's), and every
chapter's main.cpp stays within 150 lines once formatted.

Another clang-format breaks some lines differently (Debian 13's 19 does), so the check pins one
version: without clang-format-14 it is skipped (exit 77), saying so. `./kit deps --for test`
installs it where the release has it. To format a file: clang-format-14 -i FILE.

Exit 0: every file is as clang-format-14 writes it; 1: the files that are not, each named; 77:
clang-format-14 is missing.
"""
import concurrent.futures
import os
import pathlib
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
FORMATTER = "clang-format-14"
FOLDERS = ("common", "chapters", "solutions", "exercises", "tests")
MAIN_LINES = 150  # a chapter's main.cpp: one function a lecture section, at most this many lines


def sources():
    """Every C++ file of the kit's own folders (git's list when this is a clone, else the tree)."""
    listed = subprocess.run(["git", "-C", str(ROOT), "ls-files", "--", *[f"{f}/*.cpp" for f in FOLDERS],
                             *[f"{f}/*.hpp" for f in FOLDERS]], capture_output=True, text=True)
    if listed.returncode == 0 and listed.stdout.strip():
        return sorted(ROOT / line for line in listed.stdout.splitlines() if (ROOT / line).is_file())
    return sorted(p for f in FOLDERS for suffix in ("*.cpp", "*.hpp") for p in (ROOT / f).rglob(suffix))


def main():
    formatter = shutil.which(FORMATTER)
    if not formatter:
        print(f"skipped: {FORMATTER} is not installed (another version formats some lines differently); "
              "`./kit deps --for test` installs it where the release has it")
        return 77
    files = sources()

    def differs(path):
        text = path.read_bytes()
        formatted = subprocess.run([formatter, "--style=file", f"--assume-filename={path}"], input=text,
                                   capture_output=True, check=True, cwd=ROOT).stdout
        return formatted != text

    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        unformatted = [p.relative_to(ROOT) for p, bad in zip(files, pool.map(differs, files)) if bad]
    long_mains = [(p.relative_to(ROOT), n) for p in sorted((ROOT / "chapters").glob("*/main.cpp"))
                  if (n := len(p.read_text(encoding="utf-8").splitlines())) > MAIN_LINES]
    for path in unformatted:
        print(f"FAILED: {path} is not as {FORMATTER} formats it ({FORMATTER} -i {path})")
    for path, n in long_mains:
        print(f"FAILED: {path} has {n} lines, over the {MAIN_LINES} a chapter's main.cpp may take")
    if unformatted or long_mains:
        return 1
    print(f"{len(files)} C++ files as {FORMATTER} formats them; every chapter's main.cpp within {MAIN_LINES} lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
