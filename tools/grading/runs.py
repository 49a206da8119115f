"""Running an exercise's judge against a student's program: the two processes on one core, joined
by a pair of pipes, each with its limits; the judge's output and the evidence it wrote kept. A
batch's seed fixes every input, so each (exercise, program) pair runs once a batch."""
import math
import os
import pathlib
import queue
import shutil
import signal
import subprocess
import tempfile
import threading

from grading import evidence
from grading.processes import KEPT_BYTES, RUN_FILE_BYTES
from grading.sandbox import test_limits

JUDGE_MEMORY = 4 << 30  # bytes of address space for a judge


def target(ident):
    """The judge's program for exercise `ident` ("6.2" -> grade_ex6_2)."""
    return "grade_ex" + ident.replace(".", "_")


class JudgeRunner:
    """The batch's copy of the judges (shared/judges), and the runs of them against programs."""

    def __init__(self, shared, judges, sandbox, points, seed, timeout):
        self.sandbox, self.seed, self.timeout = sandbox, seed, timeout
        self.judges = shared / "judges"
        self.judges.mkdir(parents=True)
        for exercise in points["exercises"]:
            shutil.copy2(pathlib.Path(judges) / target(exercise["id"]), self.judges / target(exercise["id"]))
        self.locks, self.locks_guard = {}, threading.Lock()
        self.runs, self.runs_guard = {}, threading.Lock()
        self.cpus = queue.Queue()
        for cpu in sorted(os.sched_getaffinity(0)):
            self.cpus.put(cpu)

    def _lock(self, key):
        with self.locks_guard:
            return self.locks.setdefault(key, threading.Lock())

    def run(self, exercise, program):
        """Runs one exercise's judge against the student's program; cached per program, since a
        batch's seed fixes every input. Returns a dict of what happened."""
        key = (exercise["id"], str(program))
        with self._lock(key):
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
