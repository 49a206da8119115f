#!/usr/bin/env python3
"""Every chapter, run again with the same flags and seed as the suite's figures.NN run (the
fixture that drew FIGURES_DIR/NN-name and wrote its summary beside it, NN-name.summary.json),
writes byte-identical files and the same summary. Timings are the one exception, and they are
named so: a file whose name holds "timing"; a summary field with "timing" in its name or a unit
of time (seconds, ms, us, ns) as one of its words ("seconds", "scatter_ms", "ns_per_step"); a
run's "estimate"; a 3D page's "cost" of each pane (its header's "cost":"… s of computing per
simulated second"), and so the page's size in the summary (pages.NAME.bytes). PDFs count too: both runs set SOURCE_DATE_EPOCH, which fixes the creation date
cairo would take from the clock (figure_file.cpp). The first run was made beside the rest of the
suite, the second here: a busy machine changes nothing but timings.

Usage: reproducible_outputs.py BIN_DIR WORK_DIR FIGURES_DIR EPOCH
"""
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys

from chapter_binaries import chapter_binaries

def is_timing_key(key):
    """A field named as a timing: "timing" in it, or a unit of time as one of its words; or a run's
    "estimate" (run_estimate.hpp), whose seconds come from a calibration run, and so do its text
    and whether it was announced (from 3 s on): a busy machine changes all three."""
    return key == "estimate" or "timing" in key or bool({"seconds", "ms", "us", "ns"} & set(key.split("_")))


PAGE_COST = re.compile(rb'"cost":"[^"]*"')


def without_timings(value, out_dir, parent=""):
    """The summary with timing fields dropped and the run's own folder written as OUT."""
    if isinstance(value, dict):
        return {k: without_timings(v, out_dir, k) for k, v in value.items()
                if not is_timing_key(k) and not (k == "bytes" and parent != "" and "html" in str(value.get("path", "")))}
    if isinstance(value, list):
        return [without_timings(v, out_dir, parent) for v in value]
    if isinstance(value, str):
        return value.replace(str(out_dir), "OUT")
    return value


def outputs(out_dir, summary_text):
    files = {str(p.relative_to(out_dir)): p.read_bytes() for p in sorted(out_dir.rglob("*")) if p.is_file()}
    for name in files:
        if name.endswith(".html"):  # a pane's cost is a timing
            files[name] = PAGE_COST.sub(b'"cost":""', files[name])
    return without_timings(json.loads(summary_text), out_dir), files


def run(binary, out_dir, epoch):
    env = dict(os.environ, SOURCE_DATE_EPOCH=epoch)
    done = subprocess.run([str(binary), "--json", "--out", str(out_dir)], capture_output=True, text=True,
                          env=env, timeout=900)
    if done.returncode != 0:
        raise AssertionError(f"{binary.name}: exit {done.returncode}: {done.stderr.strip()[:400]}")
    return outputs(out_dir, done.stdout)


def drawn(figures, binary):
    """The figures.NN run's files and summary."""
    folder, summary = figures / binary.name, figures / f"{binary.name}.summary.json"
    if not folder.is_dir() or not summary.is_file():
        raise AssertionError(f"{binary.name}: no figures.{binary.name} run in {figures} (its folder and summary)")
    return outputs(folder.resolve(), summary.read_text(encoding="utf-8"))


def main(argv):
    bin_dir, work, figures, epoch = pathlib.Path(argv[1]), pathlib.Path(argv[2]).resolve(), pathlib.Path(argv[3]), argv[4]
    shutil.rmtree(work, ignore_errors=True)
    problems = []
    for binary in chapter_binaries(bin_dir):
        try:
            first = drawn(figures, binary)
            second = run(binary, work / binary.name, epoch)
        except (AssertionError, subprocess.TimeoutExpired) as error:
            problems.append(str(error))
            continue
        (summary_a, files_a), (summary_b, files_b) = first, second
        found = []
        if summary_a != summary_b:
            keys = sorted(k for k in set(summary_a) | set(summary_b) if summary_a.get(k) != summary_b.get(k))
            found.append(f"the summaries differ outside timings, under {keys}")
        if set(files_a) != set(files_b):
            found.append(f"different files: {sorted(set(files_a) ^ set(files_b))}")
        differing = sorted(n for n in set(files_a) & set(files_b)
                           if files_a[n] != files_b[n] and "timing" not in pathlib.Path(n).name)
        if differing:
            found.append(f"files differ: {differing}")
        timing_files = sum(1 for n in files_a if "timing" in pathlib.Path(n).name)
        print(f"{binary.name}: {len(files_a)} files ({timing_files} of timings), "
              f"{'identical' if not found else 'NOT identical'}")
        problems += [f"{binary.name}: {f}" for f in found]
    for problem in problems:
        print("FAILED:", problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
