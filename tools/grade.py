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
"""
import argparse
import concurrent.futures
import contextlib
import hashlib
import json
import math
import os
import pathlib
import queue
import re
import secrets
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from grading import build_log, evidence, reports, static_check, submission  # noqa: E402
from grading.program_cache import FORMAT as CACHE_FORMAT, ProgramCache, repeatable  # noqa: E402
from grading.sandbox import BUILD_MEMORY, Limits, Sandbox, SandboxUnavailable, test_limits  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
POINTS = ROOT / "tests" / "grading" / "points.json"
EXPECTED = ROOT / "tests" / "grading" / "expected_evidence.json"
REFERENCE_SEED = "20261121"  # the seed ctest and record-evidence use
SHARED = ".grading-shared"
# The system headers a student's program may read besides the precompiled ones: with those, their
# preprocessed text is part of every program's key.
SYSTEM_PROBE = "#include <fmt/format.h>\n#include <cstdio>\n#include <cstring>\n#include <stdexcept>\n"

COMPILE_LIMITS = Limits(BUILD_MEMORY, 120, True)  # one student file: 120 CPU seconds (the heaviest takes 3)
COMPILE_WALL = 300            # seconds, one compile
COMPILE_FILE_BYTES = 64 << 20  # any one file a compile writes (object, program)
RUN_FILE_BYTES = 1 << 20       # what a student's program may write (its output)
JUDGE_MEMORY = 4 << 30        # bytes of address space for a judge
KEPT_BYTES = 64 << 10          # of each log and output, what the reports folder keeps
STUDENT_DISK = 512 << 20       # bytes of compiled programs one student may add to the batch
# The student's programs are compiled at -O1: a grade is compile-bound, and without -ffast-math the
# optimisation level changes no floating-point result. The defines are the kit library's own.
COMPILE_FLAGS = ["-std=c++20", "-O1", "-DNDEBUG", "-DEIGEN_UNALIGNED_VECTORIZE=0", "-DFMT_SHARED", "-pipe",
                 "-fdiagnostics-color=never", "-fmax-errors=10"]


def target(ident):
    return "grade_ex" + ident.replace(".", "_")


def stem_of(exercise):
    return exercise["file"].removesuffix(".hpp")


def object_name(source):
    """The object of a library source (points.json "sources", a path under common/src) in
    libkit_common.a, which keeps the file's name alone: cloth/cloth.cpp -> cloth.cpp.o."""
    return pathlib.PurePosixPath(source).name + ".o"


def died_of(code, sig):
    """Whether a run ended by `sig`: bare, a negative return code; under bwrap, 128 + the signal."""
    return code is not None and code in (-sig, 128 + sig)


def keep_tail(path, text):
    """Writes at most KEPT_BYTES of `text` to `path`."""
    if len(text) > KEPT_BYTES:
        text = text[:KEPT_BYTES] + f"\n[… cut at {KEPT_BYTES} bytes]\n"
    path.write_text(text, encoding="utf-8")


def run_capped(command, timeout, **kwargs):
    """Runs `command` in its own session, stdin closed, output into a temporary file (a flood
    cannot exhaust the grader's memory); on timeout kills its whole group.
    Returns (returncode or None on timeout, the first megabyte of output)."""
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
        return code, sink.read(RUN_FILE_BYTES).decode("utf-8", errors="replace")


def digest(*parts):
    h = hashlib.sha256()
    for part in parts:
        h.update(part if isinstance(part, bytes) else str(part).encode())
        h.update(b"\0")
    return h.hexdigest()


class Batch:
    """What every student of a batch shares, built from the kit's code alone before any student's."""

    def __init__(self, out, judges, library, sandbox, points, seed, timeout, student_time, jobs, cache=None):
        self.out, self.sandbox, self.points, self.cache = out, sandbox, points, cache
        self.seed, self.timeout, self.student_time = seed, timeout, student_time
        self.shared = out / SHARED
        if self.shared.exists():
            shutil.rmtree(self.shared)
        self.programs = self.shared / "programs"
        self.programs.mkdir(parents=True)
        self.judges = self.shared / "judges"
        self.judges.mkdir()
        for exercise in points["exercises"]:
            shutil.copy2(pathlib.Path(judges) / target(exercise["id"]), self.judges / target(exercise["id"]))
        grading = ROOT / "tests" / "grading"
        self.harness = self.shared / "harness"
        shutil.copytree(grading / "remote", self.harness / "remote",
                        ignore=shutil.ignore_patterns("*.cpp"))
        shutil.copytree(grading / "harness", self.harness / "harness")
        self.loop = self.shared / "libkit_remote_student.a"
        shutil.copy2(pathlib.Path(judges) / "libkit_remote_student.a", self.loop)
        # Each exercise file's headers and objects: the kit as that exercise may see it, no more.
        self.allowed = {}
        objects_dir = self.shared / "objects"
        objects_dir.mkdir()
        # A source is named by its path under common/src ("cloth/cloth.cpp"); the archive keeps
        # its object under the file's name alone.
        wanted = sorted({object_name(s) for e in points["exercises"] for s in e.get("sources", [])})
        if wanted:
            subprocess.run(["ar", "x", str(pathlib.Path(library).resolve()), *wanted], cwd=objects_dir, check=True)
            missing = [name for name in wanted if not (objects_dir / name).is_file()]
            if missing:  # `ar x` says so, and exits 0: without them every program of theirs fails to link
                raise SystemExit(f"grade: the kit's library {library} holds no {', '.join(missing)}, which "
                                 "points.json's \"sources\" name (common/CMakeLists.txt keeps them out of the unity batches)")
        include = ROOT / "common" / "include"
        for exercise in points["exercises"]:
            stem = stem_of(exercise)
            if stem in self.allowed:
                continue
            folder = self.shared / "include" / stem
            for header in exercise["headers"]:
                (folder / header).parent.mkdir(parents=True, exist_ok=True)
                shutil.copy2(include / header, folder / header)
            self.allowed[stem] = (folder, [objects_dir / object_name(s) for s in exercise.get("sources", [])])
        # The standard library and Eigen, precompiled here from the kit's header alone: half a compile.
        self.pch = self.harness / "remote" / "student_pch.hpp"
        made = subprocess.run(["c++", *COMPILE_FLAGS, "-isystem", "/usr/include/eigen3", "-x", "c++-header",
                               str(self.pch), "-o", str(self.pch) + ".gch"], capture_output=True, text=True)
        if made.returncode != 0:
            print(f"grade: no precompiled header (each compile is slower): {made.stderr[:300]}", file=sys.stderr)
        # Everything a compile reads but the student's file: the key of its program, in this batch
        # and in the cache of later ones (grading/program_cache.py). The system headers are taken
        # preprocessed, so that an upgrade of Eigen, fmt or the C library makes new keys.
        compiler = subprocess.run(["c++", "--version"], capture_output=True, text=True).stdout
        system = subprocess.run(["c++", *COMPILE_FLAGS, "-isystem", "/usr/include/eigen3", "-E", "-x", "c++",
                                 "-include", str(self.pch), "-"], input=SYSTEM_PROBE, capture_output=True,
                                text=True).stdout.replace(str(self.shared), "<kit>")
        fmt = subprocess.run(["c++", "-print-file-name=libfmt.so"], capture_output=True,
                             text=True).stdout.strip()
        kit_files = [p for p in sorted(self.shared.rglob("*")) if p.is_file() and p.suffix != ".gch"
                     and self.programs not in p.parents and self.judges not in p.parents]
        self.inputs = digest(CACHE_FORMAT, compiler, " ".join(COMPILE_FLAGS), COMPILE_LIMITS,
                             COMPILE_FILE_BYTES, system,
                             os.path.realpath(fmt),
                             *[part for p in kit_files
                               for part in (str(p.relative_to(self.shared)), p.read_bytes())])
        self.locks, self.locks_guard = {}, threading.Lock()
        self.runs, self.runs_guard = {}, threading.Lock()
        self.compile_width = 1  # compiles per student at once: set by the batch, from --jobs and its size
        self.cpus = queue.Queue()
        for cpu in sorted(os.sched_getaffinity(0)):
            self.cpus.put(cpu)

    def lock(self, key):
        with self.locks_guard:
            return self.locks.setdefault(key, threading.Lock())

    def compile(self, stem, source_text):
        """The student's program for one exercise file, compiled once per distinct content in the
        sandbox, or taken from the cache of earlier batches. Returns (program path or None, compile
        log, bytes of disk it takes): a student is charged those bytes whoever compiled it first."""
        key = digest(self.inputs, stem, source_text)
        entry = self.programs / key
        with self.lock(key), (self.cache.claim(key) if self.cache else contextlib.nullcontext()):
            if not (entry / "done").exists():
                if not (self.cache and self.cache.fetch(key, entry)):
                    if self._compile_into(entry, stem, source_text) and self.cache:
                        self.cache.store(key, entry)
                (entry / "done").touch()
            program = entry / "program"
            return ((program if program.exists() else None),
                    (entry / "compile.log").read_text(encoding="utf-8", errors="replace"),
                    int((entry / "used").read_text()))

    def _compile_into(self, entry, stem, source_text):
        """Compiles into the folder `entry`: program (if it built), compile.log, used (bytes the
        compile wrote). Returns whether every compile of this file would end the same way: it was
        not stopped by the wall clock, a signal, a CPU limit or a full disk."""
        work = self.programs / (entry.name + ".work")
        if work.exists():
            shutil.rmtree(work)
        (work / "src").mkdir(parents=True)
        (work / "src" / f"{stem}.hpp").write_text(source_text, encoding="utf-8")
        include, objects = self.allowed[stem]
        command = ["c++", *COMPILE_FLAGS, "-include", str(self.pch), "-iquote", str(work / "src"),
                   "-iquote", str(self.harness),
                   "-I", str(include), "-isystem", "/usr/include/eigen3",
                   str(self.harness / "harness" / f"{stem}.cpp"), *map(str, objects), str(self.loop), "-lfmt",
                   "-o", str(work / "program")]
        readable = [work / "src", self.harness, include, self.loop, *objects]
        code, log = run_capped(self.sandbox.confined(command, readable, [work], COMPILE_LIMITS,
                                                     fsize=COMPILE_FILE_BYTES), COMPILE_WALL)
        # The scratch folder's name, the batch's folder and the compiler's temporary files differ
        # from run to run: a regrade, or a program from the cache, must write the same report.
        log = re.sub(r"\bcc[A-Za-z0-9]{6}\.", "cc*.",
                     log.replace(str(work), "BUILD").replace(str(self.shared), "<kit>"))
        if "No space left on device" in log or "File too large" in log:
            log = (f"error: the compile wrote a file over {COMPILE_FILE_BYTES >> 20} MiB, the most any file of a "
                   "compile may take\n") + log
        if code is None:
            log += f"\nthe compile did not finish within {COMPILE_WALL} s"
        elif died_of(code, signal.SIGXCPU):
            log += f"\nthe compile used more than {COMPILE_LIMITS.cpu} CPU seconds"
        elif died_of(code, signal.SIGXFSZ):
            log += f"\nthe compile wrote a file over {COMPILE_FILE_BYTES} bytes"
        used = sum(p.stat().st_size for p in work.rglob("*") if p.is_file())
        entry.mkdir()
        (entry / "compile.log").write_text(log, encoding="utf-8")  # whole: the verdict reads it
        (entry / "used").write_text(str(used))
        built = work / "program"  # a regular file: a link the compile planted could point anywhere
        if code == 0 and built.is_file() and not built.is_symlink():
            os.replace(work / "program", entry / "program")
        shutil.rmtree(work)
        return repeatable(code, log)

    def run(self, exercise, program):
        """Runs one exercise's judge against the student's program; cached per program, since a
        batch's seed fixes every input. Returns a dict of what happened."""
        key = (exercise["id"], str(program))
        with self.lock(key):
            with self.runs_guard:
                if key in self.runs:
                    return self.runs[key]
            result = self._run_pair(exercise, program)
            with self.runs_guard:
                self.runs[key] = result
            return result

    def _run_pair(self, exercise, program):
        cpu = self.cpus.get()  # the pair shares one core: a call and its answer cost microseconds
        try:
            to_student, to_judge = os.pipe(), os.pipe()
            with tempfile.TemporaryFile() as student_out, tempfile.TemporaryFile() as channel:
                student = subprocess.Popen(
                    ["taskset", "-c", str(cpu)] + self.sandbox.confined(
                        [str(program)], [program.parent], [], test_limits(self.timeout),
                        env={"KIT_JUDGE_FDS": f"{to_student[0]},{to_judge[1]}"}, fsize=RUN_FILE_BYTES),
                    stdin=subprocess.DEVNULL, stdout=student_out, stderr=subprocess.STDOUT,
                    pass_fds=(to_student[0], to_judge[1]), start_new_session=True)
                os.close(to_student[0]), os.close(to_judge[1])
                judge_env = {"PATH": "/usr/bin:/bin", "KIT_STUDENT_FDS": f"{to_judge[0]},{to_student[1]}",
                             "KIT_EVIDENCE_FD": str(channel.fileno())}
                # The judge is the kit's own program, but it reads what a student's program sends:
                # it gets limits too (memory, CPU seconds, file size), so that no answer can make it
                # take the machine from the class.
                judge = ["prlimit", f"--as={JUDGE_MEMORY}", f"--cpu={math.ceil(self.timeout) + 5}",
                         f"--fsize={RUN_FILE_BYTES}", "--core=0", "--",
                         str(self.judges / target(exercise["id"])), "--reporter", "compact", "--rng-seed", self.seed]
                with tempfile.TemporaryFile() as judge_out:
                    started = subprocess.Popen(["taskset", "-c", str(cpu)] + judge, stdin=subprocess.DEVNULL,
                                               stdout=judge_out, stderr=subprocess.STDOUT, env=judge_env,
                                               pass_fds=(to_judge[0], to_student[1], channel.fileno()),
                                               start_new_session=True)
                    os.close(to_judge[0]), os.close(to_student[1])
                    timed_out = False
                    try:
                        judge_code = started.wait(timeout=self.timeout)
                    except subprocess.TimeoutExpired:
                        timed_out, judge_code = True, None
                        os.killpg(started.pid, signal.SIGKILL)
                        started.wait()
                    try:
                        student_code = student.wait(timeout=5)  # the judge is done: the pipe is closed
                    except subprocess.TimeoutExpired:
                        os.killpg(student.pid, signal.SIGKILL)
                        student_code = student.wait()
                    judge_out.seek(0)
                    output = judge_out.read(RUN_FILE_BYTES).decode("utf-8", errors="replace")
                student_out.seek(0)
                printed = student_out.read(KEPT_BYTES).decode("utf-8", errors="replace")
                channel.seek(0)
                cases, end, odd = evidence.parse(channel.read(evidence.READ_BYTES + 1))
            return {"judge": judge_code, "student": student_code, "timed_out": timed_out, "output": output,
                    "printed": printed, "cases": cases, "end": end, "odd": odd}
        finally:
            self.cpus.put(cpu)


def verdict(exercise, compiled, run, expected, findings):
    """(status, message) for one exercise, from what the judge saw and how the student's program ended."""
    program, log = compiled
    if program is None:
        return "compile error", build_log.first_error(log, exercise["file"])
    student = run["student"]
    if run["timed_out"] or died_of(student, signal.SIGXCPU) or died_of(run["judge"], signal.SIGXCPU):
        return "timeout", "did not finish within the time limit: an endless loop?"
    if died_of(student, signal.SIGSYS):
        return "integrity", "the program tried to start a process or a thread, which grading forbids"
    status, reason = evidence.judge(expected, run["cases"], run["end"], run["odd"], counts=False)
    if status == "pass" and run["judge"] == 0:
        own = [f for f in findings if f["severity"] == "integrity" and f["file"] == exercise["file"]]
        if own:
            return "integrity", f"static check: {own[0]['file']}:{own[0]['line']}: {own[0]['what']}"
        return "pass", ""
    if student is not None and (student < 0 or student >= 128) and student != 128 + signal.SIGKILL:
        number = -student if student < 0 else student - 128
        name = signal.Signals(number).name if number in signal.Signals._value2member_map_ else f"signal {number}"
        return "crashed", f"the program died ({name}); {build_log.first_failure(run['output'])}".rstrip("; ")
    if status == "fail" or run["judge"] not in (0, None):
        return "fail", build_log.first_failure(run["output"]) or reason
    return "fail", f"the judge did not finish: {reason}"


def grade_one(folder, label, batch, expected):
    tree = batch.out / label
    if tree.exists():
        shutil.rmtree(tree)
    (tree / "logs").mkdir(parents=True)
    started = time.monotonic()
    points = batch.points
    allowed = submission.exercise_files(points)
    with tempfile.TemporaryDirectory(dir=batch.shared) as scratch:
        src = pathlib.Path(scratch)
        copied, missing, ignored = submission.snapshot(folder, allowed, src)
        texts = {name: (src / name).read_text(encoding="utf-8", errors="replace") for name in copied}
    kit_headers = static_check.kit_public_headers(ROOT)
    findings = []
    for name, text in texts.items():
        headers = {h for e in points["exercises"] if e["file"] == name for h in e["headers"]}
        findings += static_check.check(text, name, kit_headers, set(allowed), headers)
    placeholders = {name: (ROOT / "exercises" / name).read_text(encoding="utf-8") for name in allowed}
    # The student's files compiled side by side on the student's own share of the cores (all of them
    # for a batch of one, one each for a class): no student waits for another's compiles. A missing
    # file is graded as the untouched placeholder (it scores 0).
    stems = {e["file"]: stem_of(e) for e in points["exercises"]}
    compilers = concurrent.futures.ThreadPoolExecutor(max_workers=batch.compile_width)
    pending = {name: compilers.submit(batch.compile, stems[name], texts.get(name, placeholders[name]))
               for name in allowed}
    compilers.shutdown(wait=False)
    compiled, disk, rows = {}, 0, []
    for exercise in points["exercises"]:
        name, ident = exercise["file"], exercise["id"]
        if name not in compiled:
            program, log, used = pending[name].result()
            disk += used
            if disk > STUDENT_DISK:
                program, log = None, (f"error: the submission's programs take more than {STUDENT_DISK >> 20} MiB "
                                      "of disk, the most one student may use\n") + log
            compiled[name] = (program, log)
            keep_tail(tree / "logs" / f"compile-{stems[name]}.log", log)
        if time.monotonic() - started > batch.student_time:
            status, message = "timeout", f"the submission used up its {batch.student_time:g} s of grading time"
        else:
            run = {"student": None, "judge": None, "timed_out": False, "output": "", "printed": "", "cases": {},
                   "end": None, "odd": []}
            if compiled[name][0] is not None:
                run = batch.run(exercise, compiled[name][0])
                keep_tail(tree / "logs" / f"ex{ident}.out", run["output"])
                if run["printed"]:
                    keep_tail(tree / "logs" / f"ex{ident}.printed", run["printed"])
            status, message = verdict(exercise, compiled[name], run, expected.get(ident, {}), findings)
        if name in missing and status != "pass":
            message = f"{name} is missing from the folder; " + message
        rows.append({"id": ident, "chapter": exercise["chapter"], "title": exercise["title"], "file": name,
                     "points": exercise["points"] if status == "pass" else 0, "max_points": exercise["points"],
                     "status": status, "message": message})
    report = {"submission": label, "points": sum(r["points"] for r in rows),
              "max_points": sum(r["max_points"] for r in rows), "sandboxed": batch.sandbox.enabled,
              "seed": batch.seed, "exercises": rows, "findings": findings, "ignored": ignored}
    reports.write_submission(report, tree)
    return tree / "grade.json", report


def labels_for(folders):
    """A report name per folder: its base name, with a short hash of its path when two clash."""
    names = [(f.name or "submission") if f.name not in ("class.csv", "class.md", SHARED) else f"{f.name}-folder"
             for f in folders]
    return [n if names.count(n) == 1 else f"{n}-{hashlib.sha1(str(f).encode()).hexdigest()[:6]}"
            for n, f in zip(names, folders)]


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
                  args.jobs, cache)
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


def record_evidence(args):
    """Runs the reference judges against the reference programs and writes their cases and counts."""
    points = json.loads(POINTS.read_text(encoding="utf-8"))
    tests = pathlib.Path(args.build).resolve() / "tests"
    recorded, problems = {}, []
    for exercise in points["exercises"]:
        ident = exercise["id"]
        with tempfile.TemporaryFile() as channel:
            env = dict(os.environ, KIT_STUDENT_PROGRAM=str(tests / f"student_{stem_of(exercise)}"),
                       KIT_EVIDENCE_FD=str(channel.fileno()))
            code, output = run_capped([str(tests / target(ident)), "--reporter", "compact", "--rng-seed",
                                       REFERENCE_SEED], 300, env=env, pass_fds=(channel.fileno(),))
            channel.seek(0)
            cases, end, odd = evidence.parse(channel.read(evidence.READ_BYTES + 1))
        if code != 0 or end is None or odd or any(bad for _, bad in cases.values()):
            problems.append(f"ex {ident}: the reference does not pass (exit {code}): {build_log.first_failure(output)}")
        recorded[ident] = {name: passed for name, (passed, _) in cases.items()}
    if problems:
        print("\n".join(problems), file=sys.stderr)
        return 1
    text = json.dumps({"about": "Written by `./kit evidence` from the reference solutions, at the seed ctest uses: "
                                "the test cases of each graded exercise and the assertions each runs. A graded run "
                                "passes only when every one of these cases ran and passed.", **recorded},
                      indent=2, ensure_ascii=False) + "\n"
    pathlib.Path(args.output).write_text(text, encoding="utf-8")
    print(f"wrote {args.output}: {sum(len(c) for c in recorded.values())} test cases of {len(recorded)} exercises")
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
    return batch_command(args) if args.command == "batch" else record_evidence(args)


if __name__ == "__main__":
    sys.exit(main())
