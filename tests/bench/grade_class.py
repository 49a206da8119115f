#!/usr/bin/env python3
"""How long grading a class takes: `./kit bench grade` (not part of ctest: it measures time).

Writes a varied class from the solution markers, as a real one looks: each student has solved a
random share of the exercises (from none to all), every solved file carries the student's own
name in a comment (so no two solved files are the same, and each is compiled for itself), an
unsolved file is the untouched placeholder, and one student in ten has a file that does not
compile. Then it grades the first 1, 10 and 30 of them, each a batch of its own as an
instructor would run it (`./kit grade --jobs JOBS`) the first time (an empty program cache each),
then regrades the largest from the cache its first grading kept. It prints the wall time of each
batch, the time a further student costs between 10 and 30, the regrade's gain, and the points the
class got (a check that the batch graded what it should).

Usage: grade_class.py [--sizes 1,10,30] [--jobs N] [--work DIR]
"""
import argparse
import json
import os
import pathlib
import random
import shutil
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import exercises  # noqa: E402


def write_class(folder, count, seed=31):
    """`count` students; returns {name: the points they should get}."""
    rng = random.Random(seed)
    points = json.loads((ROOT / "tests/grading/points.json").read_text(encoding="utf-8"))
    solutions, placeholders = ROOT / "solutions", ROOT / "exercises"
    solved = exercises.expected_tree(solutions, frozenset(exercises.regions(solutions)))
    files = sorted({e["file"] for e in points["exercises"]})
    expected = {}
    for i in range(count):
        name = f"student{i + 1:03d}"
        share = rng.random()
        done = {f for f in files if rng.random() < share}
        broken = rng.choice(sorted(done)) if done and i % 10 == 9 else None
        target = folder / name
        target.mkdir(parents=True)
        for f in files:
            if f in done:
                text = f"// {name}'s work\n" + solved[f]
                if f == broken:
                    text += "\nthis line does not compile\n"
            else:
                text = (placeholders / f).read_text(encoding="utf-8")
            (target / f).write_text(text, encoding="utf-8")
        expected[name] = sum(e["points"] for e in points["exercises"] if e["file"] in done and e["file"] != broken)
    return expected


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", default="1,10,30")
    parser.add_argument("--jobs", type=int, default=len(os.sched_getaffinity(0)))
    parser.add_argument("--work", default=str(ROOT / "build" / "bench-grade"))
    args = parser.parse_args()
    sizes = [int(s) for s in args.sizes.split(",")]
    work = pathlib.Path(args.work)
    shutil.rmtree(work, ignore_errors=True)
    expected = write_class(work / "class", max(sizes))
    # The judges and the library are built before the clock starts, as for a second batch.
    subprocess.run([str(ROOT / "kit"), "grade", "--out", str(work / "warm"), "--cache", str(work / "warm-cache"),
                    str(work / "class" / "student001")], check=True, capture_output=True)
    print(f"grading a varied class on {len(os.sched_getaffinity(0))} cores, --jobs {args.jobs} "
          f"(the judges and the kit's library already built)")
    print(f"{'students':>8} {'seconds':>8} {'s/student':>10}  points as expected")
    times = {}

    def batch(size, label, cache):
        """Grades the first `size` students; prints and returns the wall time (None: it failed)."""
        names = sorted(expected)[:size]
        out = work / f"out-{size}"
        start = time.monotonic()
        run = subprocess.run([str(ROOT / "kit"), "grade", "--jobs", str(args.jobs), "--out", str(out),
                              "--cache", str(cache), *[str(work / "class" / n) for n in names]],
                             capture_output=True, text=True)
        seconds = time.monotonic() - start
        if run.returncode != 0:
            print(run.stderr[-2000:], file=sys.stderr)
            return None
        got = {n: json.loads((out / n / "grade.json").read_text(encoding="utf-8"))["points"] for n in names}
        wrong = [n for n in names if got[n] != expected[n]]
        print(f"{label:>8} {seconds:>8.1f} {seconds / size:>10.1f}  "
              + ("yes" if not wrong else f"NO: {', '.join(f'{n} {got[n]} != {expected[n]}' for n in wrong)}"))
        return seconds

    for size in sizes:  # each a first grading: a cache of its own, empty
        times[size] = batch(size, str(size), work / f"cache-{size}")
        if times[size] is None:
            return 1
    if 10 in times and 30 in times:
        print(f"a further student (from 10 to 30): {(times[30] - times[10]) / 20:.1f} s")
    largest = max(sizes)  # regraded: every program from the cache its first grading kept
    again = batch(largest, f"{largest} again", work / f"cache-{largest}")
    if again is None:
        return 1
    print(f"regrading {largest} from the cache: {times[largest] / again:.1f} times faster than the first grading")
    return 0


if __name__ == "__main__":
    sys.exit(main())
