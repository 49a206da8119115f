#!/usr/bin/env python3
"""Grade student folders: `./kit grade` calls `grade.py batch`.

Student code computes, it never judges. Each exercise is graded by two processes:
  - the judge (build/tests/grade_exN_k): the graded test, compiled from the kit's sources alone
    (tests/grading/remote/judge.hpp). It runs no student code and reaches the verdict;
  - the student's program: the student's exercise file, the kit headers points.json allows that
    exercise, a harness (tests/grading/harness/) and a loop that answers the judge's calls. It is
    compiled and run in the sandbox (grading/sandbox.py) and only returns values.
The two talk over a pair of pipes; the judge checks what comes back.

A batch:
  1. prepares OUT/.grading-shared/, before any student's code is compiled: the judges, the
     harness sources, each exercise's allowed headers and kit objects, the program loop library;
  2. draws a seed (or takes --seed, to regrade): every judge draws its random cases from it, and
     every report records it;
  3. grades the folders side by side (--jobs): copy the exercise files and nothing else
     (grading/submission.py), check them statically (grading/static_check.py), compile each
     distinct file once, keyed by its content and the batch's inputs (identical copies and
     untouched placeholders are compiled once), or take it from the programs earlier sandboxed
     batches kept (--cache: grading/program_cache.py), run each exercise's judge against its program;
  4. writes grade.json, grade.md, grade.junit.xml per folder and class.csv, class.md for the batch
     (grading/reports.py), removes everything else it made, and trims the cache to --cache-mib.
A student costs only their own grade: each compile and run has CPU, memory, file-size and time
limits; a student's compiles and runs share a time budget (--student-time) and a disk budget;
a student's output is capped; grade trees keep only the reports.

`grade.py record-evidence BUILD_DIR` runs the reference judges against the reference programs
and writes tests/grading/expected_evidence.json: each exercise's test cases and assertion counts.

This file is the command line; the grader's parts are in grading/: batch.py (a batch and one
student's grade), builds.py (the students' programs), runs.py (judge against program),
verdicts.py, evidence.py, processes.py (bounded subprocesses), sandbox.py, reports.py.
"""
import argparse
import concurrent.futures
import json
import math
import pathlib
import re
import secrets
import shutil
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from grading import evidence, record_evidence, reports  # noqa: E402
from grading.batch import Batch, grade_one, labels_for  # noqa: E402
from grading.program_cache import ProgramCache  # noqa: E402
from grading.sandbox import Sandbox, SandboxUnavailable  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
POINTS = ROOT / "tests" / "grading" / "points.json"
EXPECTED = ROOT / "tests" / "grading" / "expected_evidence.json"


def batch_command(args):
    if not (math.isfinite(args.timeout) and 0 < args.timeout <= 3600):
        print(f"grade: --timeout {args.timeout}: expected seconds in (0, 3600]", file=sys.stderr)
        return 2
    if not (math.isfinite(args.student_time) and 0 < args.student_time <= 86400):
        print(f"grade: --student-time {args.student_time}: expected seconds in (0, 86400]", file=sys.stderr)
        return 2
    if args.jobs < 1 or args.jobs > 256:
        print(f"grade: --jobs {args.jobs}: expected a whole number in [1, 256]", file=sys.stderr)
        return 2
    if not 0 <= args.cache_mib <= 1 << 20:
        print(f"grade: --cache-mib {args.cache_mib}: expected a whole number of MiB in [0, 1048576]", file=sys.stderr)
        return 2
    if args.seed is not None and not re.fullmatch(r"[1-9][0-9]{0,8}", args.seed):
        print(f"grade: --seed {args.seed}: expected a whole number in [1, 999999999]", file=sys.stderr)
        return 2
    seed = args.seed or str(1 + secrets.randbelow(999_999_999))
    points = json.loads(POINTS.read_text(encoding="utf-8"))
    expected = evidence.load_expected(EXPECTED)
    out = pathlib.Path(args.out).resolve()
    folders = [pathlib.Path(f).resolve() for f in args.folders]
    try:
        sandbox = Sandbox(enabled=not args.no_sandbox)
    except SandboxUnavailable as why:
        print(f"grade: cannot sandbox the students' code: {why}.\n"
              "Install bubblewrap, or pass --no-sandbox to grade without it (every report then says so).",
              file=sys.stderr)
        return 2
    cache = None
    if args.cache:
        try:
            cache = ProgramCache(args.cache, args.cache_mib << 20)
        except OSError as why:
            print(f"grade: --cache {args.cache}: cannot keep programs there: {why.strerror or why}", file=sys.stderr)
            return 2
    if not sandbox.enabled:
        cache = None
    out.mkdir(parents=True, exist_ok=True)
    print(f"grade: seed {seed} (regrade with --seed {seed})", file=sys.stderr, flush=True)
    if args.cache and not sandbox.enabled:
        print("grade: --no-sandbox: the programs of earlier batches are not used, nor these kept (a student's "
              "program runs with your rights here, and could change them for the next class)", file=sys.stderr)
    batch = Batch(out, args.judges, args.common_library, sandbox, points, seed, args.timeout, args.student_time,
                  cache)
    labels = labels_for(folders)
    paths = [out / label / "grade.json" for label in labels]
    batch.compile_width = max(1, args.jobs // min(args.jobs, len(folders)))

    def one(pair):
        folder, label = pair
        print(f"grading {folder}", file=sys.stderr, flush=True)
        try:
            _, report = grade_one(folder, label, batch, expected)
            reports.print_table(report)
        except (OSError, ValueError, UnicodeError) as error:  # one folder's failure never stops the batch
            print(f"grade: {folder}: could not be graded: {error}", file=sys.stderr)

    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            list(pool.map(one, zip(folders, labels)))
    finally:
        shutil.rmtree(batch.shared, ignore_errors=True)
        if cache:
            kept, removed = cache.trim()
            print(f"grade: {cache.hits} programs from earlier batches, {cache.stores} new kept; the cache "
                  f"{cache.folder} holds {kept / (1 << 20):.1f} MiB of {args.cache_mib}"
                  + (f" ({removed} least recently used removed)" if removed else ""), file=sys.stderr)
    loaded = reports.load_reports(paths)
    reports.write_class(points, loaded, out, seed)
    print("\nBatch summary (points, submission, report):")
    for path, report, problem in loaded:
        if report is None:
            print(f"  {'?':>4} / {'?':<4} {problem}: {path}")
        else:
            print(f"  {report['points']:>4} / {report['max_points']:<4} {report['submission']:<24} {path}")
    print(f"Class reports: {out / 'class.csv'}, {out / 'class.md'} (seed {seed})")
    return 0



def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    commands = parser.add_subparsers(dest="command", required=True)
    b = commands.add_parser("batch", help="grade folders")
    b.add_argument("--out", required=True)
    b.add_argument("--jobs", type=int, default=2, help="students graded side by side")
    b.add_argument("--timeout", type=float, default=30.0, help="seconds per exercise's run")
    b.add_argument("--student-time", type=float, default=900.0, help="seconds of compiling and running per student")
    b.add_argument("--seed", help="the seed of a batch to regrade (default: a new one, printed and recorded)")
    b.add_argument("--no-sandbox", action="store_true")
    b.add_argument("--cache", help="a folder keeping compiled programs for later sandboxed batches")
    b.add_argument("--cache-mib", type=int, default=1024, help="the most the cache keeps, in MiB")
    b.add_argument("--judges", required=True, help="the kit's build/tests folder: the judges and the program loop")
    b.add_argument("--common-library", required=True,
                   help="the kit's libkit_common.a: the objects an exercise may link")
    b.add_argument("folders", nargs="+")
    r = commands.add_parser("record-evidence", help="record the reference's cases and assertion counts")
    r.add_argument("build")
    r.add_argument("--output", default=str(EXPECTED))
    args = parser.parse_args()
    if args.command == "batch":
        return batch_command(args)
    return record_evidence.record(json.loads(POINTS.read_text(encoding="utf-8")), args.build, args.output)


if __name__ == "__main__":
    sys.exit(main())
