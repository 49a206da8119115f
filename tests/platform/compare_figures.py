#!/usr/bin/env python3
"""Compares the data the chapters wrote on two systems (two copies of build/figures/, say from
tests/platform/debian.sh bookworm and trixie): every data file (.dat, .csv, .obj, .json) present in
both, number by number as printed. Prints, per chapter, how many files are equal to the printed
precision, and for each that differs: how many numbers differ, the largest relative difference,
and the first difference with its line. Exit 0 when every file compared is equal, 1 otherwise
(the list is then what a README or a note has to explain), 2 on bad arguments.

Usage: compare_figures.py FIGURES_A FIGURES_B
"""
import math
import pathlib
import re
import sys

DATA = {".dat", ".csv", ".obj", ".json"}
NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|[-+]?(?:inf|nan)", re.IGNORECASE)


def tokens(text):
    """(line number, token) for every number and every other word, in order."""
    out = []
    for number, line in enumerate(text.splitlines(), 1):
        for token in re.split(r"[\s,;:\[\]{}\"]+", line):
            if token:
                out.append((number, token))
    return out


def as_float(token):
    if NUMBER.fullmatch(token):
        try:
            return float(token)
        except ValueError:
            return None
    return None


def compare(a, b):
    """(numbers differing, largest relative difference, first difference) of two files' texts."""
    ta, tb = tokens(a), tokens(b)
    differing, largest, first = 0, 0.0, None
    if len(ta) != len(tb):
        first = f"{len(ta)} words against {len(tb)}"
    for (line, x), (_, y) in zip(ta, tb):
        if x == y:
            continue
        differing += 1
        fx, fy = as_float(x), as_float(y)
        if fx is not None and fy is not None and math.isfinite(fx) and math.isfinite(fy):
            scale = max(abs(fx), abs(fy))
            largest = max(largest, abs(fx - fy) / scale if scale else 0.0)
        else:
            largest = math.inf
        if first is None:
            first = f"line {line}: {x} against {y}"
    if len(ta) != len(tb):
        differing += abs(len(ta) - len(tb))
    return differing, largest, first


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    a, b = (pathlib.Path(p) for p in sys.argv[1:])
    for folder in (a, b):
        if not folder.is_dir():
            print(f"compare_figures.py: {folder}: no such folder", file=sys.stderr)
            return 2
    files_a = {p.relative_to(a) for p in a.rglob("*") if p.suffix in DATA and p.is_file()}
    files_b = {p.relative_to(b) for p in b.rglob("*") if p.suffix in DATA and p.is_file()}
    only = sorted(files_a ^ files_b)
    differ = 0
    chapters = sorted({p.parts[0] for p in files_a | files_b})
    for chapter in chapters:
        mine = sorted(p for p in files_a & files_b if p.parts[0] == chapter)
        rows = []
        for path in mine:
            n, largest, first = compare((a / path).read_text(errors="replace"), (b / path).read_text(errors="replace"))
            if n:
                rows.append(f"  {path}: {n} numbers differ, largest relative difference {largest:.2g}; first: {first}")
        differ += len(rows)
        print(f"{chapter}: {len(mine) - len(rows)} of {len(mine)} data files equal to the printed precision")
        print("\n".join(rows)) if rows else None
    for path in only:
        print(f"  {path}: only in {a if path in files_a else b}")
    print(f"{differ} files differ, {len(only)} in one folder only")
    return 0 if differ == 0 and not only else 1


if __name__ == "__main__":
    sys.exit(main())
