"""Building a student's program for one exercise file: the kit as that exercise may see it (its
allowed headers and library objects, the harness, the program loop), a precompiled header, and
one sandboxed compile per distinct file, keyed by everything the compile reads so that identical
copies, untouched placeholders and programs kept by earlier batches (program_cache.py) cost none."""
import contextlib
import hashlib
import os
import pathlib
import re
import shutil
import signal
import subprocess
import sys
import threading

from grading.processes import died_of, run_capped
from grading.program_cache import FORMAT as CACHE_FORMAT, repeatable
from grading.sandbox import BUILD_MEMORY, Limits

ROOT = pathlib.Path(__file__).resolve().parents[2]
# The system headers a student's program may read besides the precompiled ones: with those, their
# preprocessed text is part of every program's key.
SYSTEM_PROBE = "#include <fmt/format.h>\n#include <cstdio>\n#include <cstring>\n#include <stdexcept>\n"
COMPILE_LIMITS = Limits(BUILD_MEMORY, 120, True)  # one student file: 120 CPU seconds (the heaviest takes 3)
COMPILE_WALL = 300             # seconds, one compile
COMPILE_FILE_BYTES = 64 << 20  # any one file a compile writes (object, program)
# The student's programs are compiled at -O1: a grade is compile-bound, and without -ffast-math the
# optimisation level changes no floating-point result. The defines are the kit library's own.
COMPILE_FLAGS = ["-std=c++20", "-O1", "-DNDEBUG", "-DEIGEN_UNALIGNED_VECTORIZE=0", "-DFMT_SHARED", "-pipe",
                 "-fdiagnostics-color=never", "-fmax-errors=10"]


def stem_of(exercise):
    return exercise["file"].removesuffix(".hpp")


def object_name(source):
    """The object of a library source (points.json "sources", a path under common/src) in
    libkit_common.a, which keeps the file's name alone: cloth/cloth.cpp -> cloth.cpp.o."""
    return pathlib.PurePosixPath(source).name + ".o"


def digest(*parts):
    h = hashlib.sha256()
    for part in parts:
        h.update(part if isinstance(part, bytes) else str(part).encode())
        h.update(b"\0")
    return h.hexdigest()


class ProgramBuilder:
    """Prepares, in the batch's shared folder and from the kit's files alone, what every compile
    reads; then compiles student files into programs/ (or takes them from `cache`)."""

    def __init__(self, shared, judges, library, sandbox, points, cache=None):
        self.shared, self.sandbox, self.cache = shared, sandbox, cache
        self.programs = shared / "programs"
        self.programs.mkdir(parents=True)
        grading = ROOT / "tests" / "grading"
        self.harness = shared / "harness"
        shutil.copytree(grading / "remote", self.harness / "remote",
                        ignore=shutil.ignore_patterns("*.cpp"))
        shutil.copytree(grading / "harness", self.harness / "harness")
        self.loop = shared / "libkit_remote_student.a"
        shutil.copy2(pathlib.Path(judges) / "libkit_remote_student.a", self.loop)
        # Each exercise file's headers and objects: the kit as that exercise may see it, no more.
        self.allowed = {}
        objects_dir = shared / "objects"
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
            folder = shared / "include" / stem
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
        # and in the cache of later ones (program_cache.py). The system headers are taken
        # preprocessed, so that an upgrade of Eigen, fmt or the C library makes new keys.
        compiler = subprocess.run(["c++", "--version"], capture_output=True, text=True).stdout
        system = subprocess.run(["c++", *COMPILE_FLAGS, "-isystem", "/usr/include/eigen3", "-E", "-x", "c++",
                                 "-include", str(self.pch), "-"], input=SYSTEM_PROBE, capture_output=True,
                                text=True).stdout.replace(str(shared), "<kit>")
        fmt = subprocess.run(["c++", "-print-file-name=libfmt.so"], capture_output=True,
                             text=True).stdout.strip()
        # The judges are not read by a compile: another folder of the batch (runs.py).
        skipped = (self.programs, shared / "judges")
        kit_files = [p for p in sorted(shared.rglob("*")) if p.is_file() and p.suffix != ".gch"
                     and not any(folder in p.parents for folder in skipped)]
        self.inputs = digest(CACHE_FORMAT, compiler, " ".join(COMPILE_FLAGS), COMPILE_LIMITS,
                             COMPILE_FILE_BYTES, system,
                             os.path.realpath(fmt),
                             *[part for p in kit_files
                               for part in (str(p.relative_to(shared)), p.read_bytes())])
        self.locks, self.locks_guard = {}, threading.Lock()

    def _lock(self, key):
        with self.locks_guard:
            return self.locks.setdefault(key, threading.Lock())

    def compile(self, stem, source_text):
        """The student's program for one exercise file, compiled once per distinct content in the
        sandbox, or taken from the cache of earlier batches. Returns (program path or None, compile
        log, bytes of disk it takes): a student is charged those bytes whoever compiled it first."""
        key = digest(self.inputs, stem, source_text)
        entry = self.programs / key
        with self._lock(key), (self.cache.claim(key) if self.cache else contextlib.nullcontext()):
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
