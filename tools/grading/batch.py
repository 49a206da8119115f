"""A batch: what its students share (the shared folder: builds.py's inputs, runs.py's judges), and
one student's grade from it: their files copied (submission.py) and checked (static_check.py),
each compiled on the student's own share of the cores, each exercise's judge run against its
program, every verdict (verdicts.py) within the student's time and disk budgets, the reports
written (reports.py)."""
import concurrent.futures
import hashlib
import pathlib
import shutil
import tempfile
import time

from grading import reports, static_check, submission
from grading.builds import ROOT, ProgramBuilder, stem_of
from grading.processes import keep_tail
from grading.runs import JudgeRunner
from grading.verdicts import verdict

SHARED = ".grading-shared"
STUDENT_DISK = 512 << 20  # bytes of compiled programs one student may add to the batch


class Batch:
    """What every student of a batch shares, built from the kit's code alone before any student's."""

    def __init__(self, out, judges, library, sandbox, points, seed, timeout, student_time, cache=None):
        self.out, self.sandbox, self.points = out, sandbox, points
        self.seed, self.student_time = seed, student_time
        self.shared = out / SHARED
        if self.shared.exists():
            shutil.rmtree(self.shared)
        self.runner = JudgeRunner(self.shared, judges, sandbox, points, seed, timeout)
        self.builder = ProgramBuilder(self.shared, judges, library, sandbox, points, cache)
        self.compile_width = 1  # compiles per student at once: set by the batch, from --jobs and its size

    def compile(self, stem, source_text):
        return self.builder.compile(stem, source_text)

    def run(self, exercise, program):
        return self.runner.run(exercise, program)


def grade_one(folder, label, batch, expected):
    """Grades one folder into OUT/label/; returns the path of its grade.json and the report."""
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
