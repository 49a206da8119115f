#!/usr/bin/env python3
"""Grade student folders: `./kit grade` calls `grade.py batch`.

For each folder, in its own grade tree OUT/NAME/:
  1. copy the exercise files named in points.json, and nothing else, into OUT/NAME/src/
     (grading/submission.py); statically check them (grading/static_check.py);
  2. configure and build the graded programs against that copy, inside the sandbox
     (grading/sandbox.py), one program per exercise, `ninja -k 0` so a file that does not compile
     costs only the exercises written in it; they link the kit's library as `./kit` built it once
     for the batch (--common-library), and the Catch2 main and precompiled header (Catch2, Eigen)
     that OUT/.grading-shared/ builds once for the batch from the kit's code alone, read-only in
     every sandbox: a tree compiles only its graded programs;
  3. run each graded program inside the sandbox, with a memory limit, a timeout (wall clock and
     CPU seconds) and no right to start a process, and read the evidence it writes on a channel
     the grader opened (grading/evidence.py);
  4. write grade.json, grade.md, grade.junit.xml; then class.csv and class.md for the batch
     (grading/reports.py). Reports are written here, outside the sandbox, never by a test.

`grade.py record-evidence BUILD_DIR` runs the reference (solutions/) graded programs of a build
and writes tests/grading/expected_evidence.json: the test cases of each exercise and their
assertion counts, which a submission's run must match.
"""
import argparse
import filecmp
import hashlib
import math
import json
import os
import pathlib
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from grading import build_log, evidence, reports, static_check, submission  # noqa: E402
from grading.sandbox import BUILD_LIMITS, Sandbox, SandboxUnavailable, test_limits  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
POINTS = ROOT / "tests" / "grading" / "points.json"
EXPECTED = ROOT / "tests" / "grading" / "expected_evidence.json"
SEED = "20261121"  # the same --rng-seed the CTest entries use


def target(ident):
    return "grade_ex" + ident.replace(".", "_")


OUTPUT_BYTES = 16 << 20  # what a graded process may write, output and evidence alike


def run_limited(command, timeout, **kwargs):
    """Runs `command` in its own session, stdin closed, its output into a temporary file (a
    flood cannot exhaust the grader's memory; RLIMIT_FSIZE caps it inside the sandbox); on
    timeout kills the whole group. Returns (returncode or None on timeout, output text)."""
    with tempfile.TemporaryFile() as sink:
        process = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=sink, stderr=subprocess.STDOUT,
                                   start_new_session=True, **kwargs)
        try:
            code = process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
            code = None
        sink.seek(0)
        return code, sink.read(OUTPUT_BYTES).decode("utf-8", errors="replace")


def evidence_fd_for(path):
    """The descriptor number of a run's evidence channel: fixed for a path, different across trees."""
    return random.Random(str(path)).randrange(10, 200)


def run_with_evidence(command, evidence_path, fd_number, timeout):
    """Runs a graded program with the evidence channel, a capped file, open as `fd_number`.
    The command carries KIT_EVIDENCE_FD itself (the sandbox clears the environment)."""
    with open(evidence_path, "wb") as sink:
        os.dup2(sink.fileno(), fd_number)
        try:
            return run_limited(command, timeout, pass_fds=(fd_number,))
        finally:
            os.close(fd_number)


def died_of(code, sig):
    """Whether a run ended by `sig`: bare, a negative return code; under bwrap, 128 + the signal."""
    return code in (-sig, 128 + sig)


def verdict(exercise, binary, run, expected, errors, findings):
    """(status, message) for one exercise."""
    ident = exercise["id"]
    if target(ident) in errors:  # checked first: a failed build must never run an older binary
        return "compile error", errors[target(ident)]
    if not binary.exists():
        return "not run", "the test program was not built (see build.log)"
    code, output, cases, end, odd = run
    # An exit status of 128 + n reads as signal n only when the run never reached its end
    # record: Catch2 exits with the number of failed checks (up to 255), which can be 152 or 159.
    if code is None or (end is None and died_of(code, signal.SIGXCPU)):  # wall clock or CPU seconds ran out
        return "timeout", "did not finish within the time limit: an endless loop?"
    if end is None and died_of(code, signal.SIGSYS):  # the sandbox's filter: a graded test may not fork
        return "integrity", "the test process tried to start a process or a thread, which grading forbids"
    status, reason = evidence.judge(expected, cases, end, odd)
    signal_caught = re.search(r"(SIG[A-Z]+) - ([^'\n]*)", output)
    if status == "fail" and signal_caught:  # Catch turns a fatal signal into a failed check
        return "crashed", f"the test process died: {signal_caught.group(1)} ({signal_caught.group(2).strip()})"
    if status == "fail":
        return "fail", build_log.first_failure(output) or reason
    if end is None and (code < 0 or code >= 128):
        return "crashed", f"the test process died (exit {code}); {build_log.first_failure(output)}".rstrip("; ")
    if status == "pass" and code != 0:
        return "integrity", f"the test process exited with code {code} after passing every check"
    if status == "pass":
        own = [f for f in findings if f["severity"] == "integrity" and f["file"] == exercise["file"]]
        if own:
            return "integrity", f"static check: {own[0]['file']}:{own[0]['line']}: {own[0]['what']}"
    return status, reason


# The graded programs are compiled at -O1: a grade is compile-bound (each program runs in well under
# a second): at -O1 a tree grades in 68 s here against 79 s at -O3, and without -ffast-math the
# optimisation level changes no floating-point result. The kit's library they link stays -O3.
GRADED_OPTIMISATION = "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG"


def shared_library(library, tree):
    """The kit's prebuilt library (`--common-library`), copied into the tree, whose build sees
    nothing of the kit's build folder; copied only when it changed, keeping its time stamp, so
    that a regrade relinks nothing. Returns the path for KIT_COMMON_LIBRARY ("" without one)."""
    if not library:
        return ""
    copy = tree / "kit-common" / "libkit_common.a"
    copy.parent.mkdir(exist_ok=True)
    if not copy.exists() or not filecmp.cmp(library, copy, shallow=False):
        shutil.copy2(library, copy)
    return str(copy)


SHARED_TREE = ".grading-shared"  # the batch's Catch2 main and precompiled header, in OUT/ beside the grade trees


def configure(sandbox, tree, build, impl, common, shared):
    """Configures a grade tree, inside the sandbox, unless its cache already holds these settings
    (the batch's shared tree too: its flags must be the graded programs' own for GCC to use its
    precompiled header). Returns (configured, cmake's output)."""
    cache = build / "CMakeCache.txt"
    cached = cache.read_text(encoding="utf-8", errors="replace") if cache.exists() else ""
    settings = [f"KIT_IMPL:STRING={impl}", f"KIT_COMMON_LIBRARY:FILEPATH={common}", f"KIT_GRADING_SHARED:PATH={shared}"]
    if all(f"{line}\n" in cached for line in settings) and (build / "build.ninja").exists():
        return True, ""
    code, log = run_limited(sandbox.wrap(["cmake", "-S", str(ROOT), "-B", str(build), "-G", "Ninja",
                                          "-DCMAKE_BUILD_TYPE=Release", GRADED_OPTIMISATION, "-DKIT_GRADING_ONLY=ON",
                                          *[f"-D{line}" for line in settings]], tree, True, BUILD_LIMITS), 600)
    return code == 0, log


def batch_shared(out, sandbox, library):
    """Builds the graded programs' Catch2 main and precompiled header (tests/support/) once for
    the batch, from the kit's code alone and before any student's code is compiled; every grade
    tree then reads them, read-only (only in the sandbox: without it, a test could rewrite them).
    Returns the build folder to pass as KIT_GRADING_SHARED, or "" without a sandbox or when they
    could not be built (each tree then builds its own: slower, and the grades are the same)."""
    if not sandbox.enabled:
        return ""  # unconfined, a graded test could rewrite it for every classmate after it
    tree = out / SHARED_TREE
    code = None
    try:
        tree.mkdir(parents=True, exist_ok=True)
        build = tree / "build"
        common = shared_library(library, tree)
        configured, log = configure(sandbox, tree, build, ROOT / "exercises", common, "")
        if configured:
            code, more = run_limited(sandbox.wrap(["cmake", "--build", str(build), "--target", "kit_grading_shared"],
                                                  tree, True, BUILD_LIMITS), 600)
            log += more
        (tree / "build.log").write_text(log, encoding="utf-8")
    except OSError as error:
        print(f"grade: {tree}: {error}", file=sys.stderr)
    if code != 0:
        print(f"grade: the batch's shared Catch2 main and precompiled header could not be built (see "
              f"{tree / 'build.log'}); each tree builds its own", file=sys.stderr)
        return ""
    sandbox.share(build)
    return str(build)


def grade_one(folder, label, out, points, expected, sandbox, jobs, timeout, library, shared):
    tree = out / label
    tree.mkdir(parents=True, exist_ok=True)
    src, build = tree / "src", tree / "build"
    common = shared_library(library, tree)
    allowed = submission.exercise_files(points)
    copied, missing, ignored = submission.snapshot(folder, allowed, src)
    kit_headers = static_check.kit_public_headers(ROOT)
    findings = []
    for name in copied:
        findings += static_check.check((src / name).read_text(encoding="utf-8", errors="replace"), name,
                                       kit_headers, set(allowed))
    configured, log = configure(sandbox, tree, build, src, common, shared)
    if log:
        (tree / "configure.log").write_text(log, encoding="utf-8")
    rows = []
    errors = {}
    if configured:
        # A program that fails to build, for whatever reason (an error, a log cut short, a build
        # stopped by its time limit), must never run an older binary: every one is relinked.
        for old in (build / "tests").glob("grade_ex*"):
            if old.is_file():
                old.unlink()
        _, log = run_limited(sandbox.wrap(["cmake", "--build", str(build), "-j", str(jobs), "--", "-k", "0"],
                                          tree, True, BUILD_LIMITS), 3600)
        (tree / "build.log").write_text(log, encoding="utf-8")
        errors = build_log.compile_errors(log, allowed)
    evidence_dir = tree / "evidence"
    evidence_dir.mkdir(exist_ok=True)
    for exercise in points["exercises"]:
        ident = exercise["id"]
        binary = build / "tests" / target(ident)
        if not configured:
            status, message = "error", "the folder could not be configured (see configure.log)"
        else:
            run = (None, "", {}, None, [])
            if binary.exists():
                channel = evidence_dir / f"ex{ident}.txt"
                fd = evidence_fd_for(channel)
                command = sandbox.wrap([str(binary), "--reporter", "compact", "--rng-seed", SEED], tree, False,
                                       test_limits(timeout), env={"KIT_EVIDENCE_FD": str(fd)})
                code, output = run_with_evidence(command, channel, fd, timeout)
                (evidence_dir / f"ex{ident}.out").write_text(output, encoding="utf-8")
                run = (code, output, *evidence.read(channel))
            status, message = verdict(exercise, binary, run, expected.get(ident, {}), errors, findings)
        if exercise["file"] in missing and status != "pass":
            message = f"{exercise['file']} is missing from the folder; " + message
        rows.append({"id": ident, "chapter": exercise["chapter"], "title": exercise["title"], "file": exercise["file"],
                     "points": exercise["points"] if status == "pass" else 0, "max_points": exercise["points"],
                     "status": status, "message": message})
    report = {"submission": label, "points": sum(r["points"] for r in rows),
              "max_points": sum(r["max_points"] for r in rows), "sandboxed": sandbox.enabled,
              "exercises": rows, "findings": findings, "ignored": ignored}
    reports.write_submission(report, tree)
    reports.print_table(report)
    return tree / "grade.json"


def labels_for(folders):
    """A report name per folder: its base name, with a short hash of its path when two clash."""
    names = [(f.name or "submission") if f.name not in ("class.csv", "class.md", SHARED_TREE) else f"{f.name}-folder"
             for f in folders]
    return [n if names.count(n) == 1 else f"{n}-{hashlib.sha1(str(f).encode()).hexdigest()[:6]}"
            for n, f in zip(names, folders)]


def batch(args):
    if not (math.isfinite(args.timeout) and 0 < args.timeout <= 3600):
        print(f"grade: --timeout {args.timeout}: expected seconds in (0, 3600]", file=sys.stderr)
        return 2
    points = json.loads(POINTS.read_text(encoding="utf-8"))
    expected = evidence.load_expected(EXPECTED)
    out = pathlib.Path(args.out).resolve()
    folders = [pathlib.Path(f).resolve() for f in args.folders]
    try:
        sandbox = Sandbox(ROOT, hidden=[out, ROOT / "build", *folders], enabled=not args.no_sandbox)
    except SandboxUnavailable as why:
        print(f"grade: cannot sandbox the students' code: {why}.\n"
              "Install bubblewrap, or pass --no-sandbox to grade without it (every report then says so).",
              file=sys.stderr)
        return 2
    out.mkdir(parents=True, exist_ok=True)
    paths = []
    shared = batch_shared(out, sandbox, args.common_library)
    for folder, label in zip(folders, labels_for(folders)):
        print(f"grading {folder}", file=sys.stderr, flush=True)
        try:
            paths.append(grade_one(folder, label, out, points, expected, sandbox, args.jobs, args.timeout,
                                   args.common_library, shared))
        except (OSError, ValueError, UnicodeError) as error:  # one folder's failure never stops the batch
            print(f"grade: {folder}: could not be graded: {error}", file=sys.stderr)
            paths.append(out / label / "grade.json")  # absent or stale: the summary names it
    loaded = reports.load_reports(paths)
    reports.write_class(points, loaded, out)
    print("\nBatch summary (points, submission, report):")
    for path, report, problem in loaded:
        if report is None:
            print(f"  {'?':>4} / {'?':<4} {problem}: {path}")
        else:
            print(f"  {report['points']:>4} / {report['max_points']:<4} {report['submission']:<24} {path}")
    print(f"Class reports: {out / 'class.csv'}, {out / 'class.md'}")
    return 0


def record_evidence(args):
    """Runs the reference graded programs and writes their cases and assertion counts."""
    points = json.loads(POINTS.read_text(encoding="utf-8"))
    build = pathlib.Path(args.build).resolve()
    recorded, problems = {}, []
    for exercise in points["exercises"]:
        ident = exercise["id"]
        binary = build / "tests" / target(ident)
        channel = build / f"evidence-ex{ident}.txt"
        fd = evidence_fd_for(channel)
        code, output = run_with_evidence(["env", f"KIT_EVIDENCE_FD={fd}", str(binary), "--reporter", "compact",
                                          "--rng-seed", SEED], channel, fd, 300)
        cases, end, odd = evidence.read(channel)
        if code != 0 or end is None or odd or any(bad for _, bad in cases.values()):
            problems.append(f"ex {ident}: the reference does not pass (exit {code}): {build_log.first_failure(output)}")
        recorded[ident] = {name: passed for name, (passed, _) in cases.items()}
    if problems:
        print("\n".join(problems), file=sys.stderr)
        return 1
    text = json.dumps({"about": "Written by `./kit evidence` from the reference solutions: the test cases of each "
                                "graded exercise and the assertions each runs. A submission passes an exercise only "
                                "when its run shows exactly these.", **recorded}, indent=2, ensure_ascii=False) + "\n"
    pathlib.Path(args.output).write_text(text, encoding="utf-8")
    print(f"wrote {args.output}: {sum(len(c) for c in recorded.values())} test cases of {len(recorded)} exercises")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    commands = parser.add_subparsers(dest="command", required=True)
    b = commands.add_parser("batch", help="grade folders")
    b.add_argument("--out", required=True)
    b.add_argument("--jobs", type=int, default=2)
    b.add_argument("--timeout", type=float, default=30.0, help="seconds per graded program")
    b.add_argument("--no-sandbox", action="store_true")
    b.add_argument("--common-library", default="", help="a libkit_common.a built from this kit (./kit passes its "
                   "own): the grade trees link it instead of each compiling the library")
    b.add_argument("folders", nargs="+")
    r = commands.add_parser("record-evidence", help="record the reference's cases and assertion counts")
    r.add_argument("build")
    r.add_argument("--output", default=str(EXPECTED))
    args = parser.parse_args()
    return batch(args) if args.command == "batch" else record_evidence(args)


if __name__ == "__main__":
    sys.exit(main())
