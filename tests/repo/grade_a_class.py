#!/usr/bin/env python3
"""A class of six is graded in one command, and student code cannot change grades.

The six submissions, generated from the solution markers:
  complete      every exercise solved
  empty         an empty folder
  broken        midpoint.hpp does not compile
  segfaults     ex 2.2 writes through a null pointer
  loops         ex 3.2 never returns
  adversary     solved, but six files attack the grader:
    amplification.hpp   a static initialiser writes outside its tree: a marker file, the kit's
                        points.json and a new file in tests/grading/, a line appended to every
                        classmate's file, the classmates' grade.json, and the batch's shared
                        Catch2 main and precompiled header
    rk4.hpp             std::_Exit(0) in a static initialiser (ctest would say "Passed")
    symplectic_euler.hpp  #define CHECK(...) to silence the checks, with a wrong method
    spring_system.hpp   #include of the kit's own solutions/ file, by absolute path
    implicit_euler.hpp  reads another submission's file
    pi_controller.hpp   starts processes from a static initialiser with posix_spawn (declared by
                        hand, so no header gives it away), as a fork bomb would: the sandbox
                        kills the test at the first one (bounded to 64 harmless processes, so
                        that a sandbox without the filter does not hurt the machine)
  and it ships a fake Catch2 (catch2/catch.hpp, catch2/catch_all.hpp, catch2/catch_test_macros.hpp,
  kit_catch.hpp) and kit/state.hpp that would make every check pass.
Checks: class.csv is right; every attacked item scores 0 (integrity, compile error or fail);
the untouched items still score; the compile error names the student's file and line;
regrading writes the same reports byte for byte; nothing outside the grade trees changed.

Usage: grade_a_class.py WORK_DIR
"""
import csv
import hashlib
import json
import pathlib
import re
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
# The headers a submission could plant to fake the test framework, under both Catch2 generations.
CATCH_SHADOWS = ("catch2/catch.hpp", "catch2/catch_all.hpp", "catch2/catch_test_macros.hpp", "kit_catch.hpp")
sys.path.insert(0, str(ROOT / "tools"))
import exercises  # noqa: E402


def write(folder, files):
    folder.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        (folder / name).parent.mkdir(parents=True, exist_ok=True)
        (folder / name).write_text(text, encoding="utf-8")


def prepend(text, code):
    """Inserts `code` after the first `namespace kit {` of a file."""
    marker = "namespace kit {\n"
    i = text.index(marker) + len(marker)
    return text[:i] + code + text[i:]


def fingerprint(paths):
    """{path: sha1} of every file under `paths`."""
    found = {}
    for base in paths:
        for p in sorted(pathlib.Path(base).rglob("*")):
            if p.is_file() and "build" not in p.relative_to(base).parts[:1]:
                found[str(p)] = hashlib.sha1(p.read_bytes()).hexdigest()
    return found


def fingerprint_reports(out):
    """{report path: sha1} of every report the grader writes."""
    names = ("grade.json", "grade.md", "grade.junit.xml", "class.csv", "class.md")
    return {str(p): hashlib.sha1(p.read_bytes()).hexdigest() for p in sorted(out.rglob("*"))
            if p.name in names and "build" not in p.parts}


def main(argv):
    work = pathlib.Path(argv[1]).resolve()
    if work.exists():
        shutil.rmtree(work)
    classroom, out, outside = work / "class", work / "out", work / "outside"
    outside.mkdir(parents=True)
    solutions = ROOT / "solutions"
    points = json.loads((ROOT / "tests/grading/points.json").read_text(encoding="utf-8"))
    value = {e["id"]: e["points"] for e in points["exercises"]}
    total = sum(value.values())
    solved = exercises.expected_tree(solutions, frozenset(exercises.regions(solutions)))
    names = ["complete", "empty", "broken", "segfaults", "loops", "adversary"]

    write(classroom / "complete", solved)
    (classroom / "empty").mkdir(parents=True)
    write(classroom / "broken", dict(solved, **{"midpoint.hpp": solved["midpoint.hpp"].replace("return u + dt", "return u +* dt")}))
    write(classroom / "segfaults", dict(solved, **{"implicit_euler_spring.hpp": solved["implicit_euler_spring.hpp"].replace(
        "  const double k = spring.stiffness", "  *static_cast<volatile int*>(nullptr) = 1;\n  const double k = spring.stiffness")}))
    write(classroom / "loops", dict(solved, **{"rk4.hpp": solved["rk4.hpp"].replace(
        "  const auto h = dt / 2;", "  for (volatile int spin = 0;; spin = spin + 1) {}\n  const auto h = dt / 2;")}))

    classmates = [str(classroom / n / "explicit_euler.hpp") for n in names[:-1]]
    reports = [str(out / n / "grade.json") for n in names[:-1]]
    # The batch's shared build, which every classmate's tree compiles and links with.
    shared = out / ".grading-shared" / "build"
    shared_files = {shared / "tests/libkit_catch_main.a": b"!<arch>",
                    shared / "tests/CMakeFiles/kit_test_pch.dir/cmake_pch.hxx.gch": b"gpch"}
    targets = [str(outside / "pwned"), str(ROOT / "tests/grading/points.json"), str(ROOT / "tests/grading/extra.cpp"),
               *map(str, shared_files)]
    attack = ("inline const bool kit_attack = [] {\n"
              + "".join(f'  {{ std::ofstream f("{t}"); f << "{{}}"; }}\n' for t in targets + reports)
              + "".join(f'  {{ std::ofstream f("{c}", std::ios::app); f << "// tampered\\n"; }}\n' for c in classmates)
              + "  return true;\n}();\n")
    adversary = dict(solved)
    adversary["amplification.hpp"] = prepend(solved["amplification.hpp"].replace("#include <complex>", "#include <complex>\n#include <fstream>"), attack)
    adversary["rk4.hpp"] = prepend(solved["rk4.hpp"].replace("#include <kit/not_implemented.hpp>", "#include <cstdlib>\n#include <kit/not_implemented.hpp>"),
                                   "inline const bool kit_quit = (std::_Exit(0), true);\n")
    adversary["symplectic_euler.hpp"] = solved["symplectic_euler.hpp"].replace(
        "#pragma once", "#pragma once\n#define CHECK(...) ((void)0)\n#define REQUIRE(...) ((void)0)").replace(
        "u.template tail<D>() + dt * accel", "u.template tail<D>() - dt * accel")
    adversary["spring_system.hpp"] = solved["spring_system.hpp"].replace(
        "#include <kit/spring.hpp>", f'#include <kit/spring.hpp>\n#include "{solutions / "spring_system.hpp"}"')
    adversary["implicit_euler.hpp"] = prepend(solved["implicit_euler.hpp"].replace("#include <cmath>", "#include <cmath>\n#include <fstream>\n#include <string>"),
        f'inline const std::string kit_peek = [] {{ std::ifstream f("{classroom / "complete" / "midpoint.hpp"}"); '
        'std::string s; std::getline(f, s); return s; }();\n')
    adversary["pi_controller.hpp"] = prepend(solved["pi_controller.hpp"], (
        'extern "C" int posix_spawn(int*, const char*, const void*, const void*, char* const*, char* const*);\n'
        "inline const int kit_spawned = [] {\n"
        '  char name[] = "true";\n'
        "  char* argv[] = {name, nullptr};\n"
        "  int pid = 0, n = 0;\n"
        '  while (n < 64 && posix_spawn(&pid, "/usr/bin/true", nullptr, nullptr, argv, argv + 1) == 0) ++n;\n'
        "  return n;\n"
        "}();\n"))
    # Catch2 v2's one header, v3's, the kit's layer over both: none may stand in for the real ones.
    fake_catch = "#pragma once\n#define TEST_CASE(...) void fake()\n#define CHECK(...)\n"
    for shadow in CATCH_SHADOWS:
        adversary[shadow] = fake_catch
    adversary["kit/state.hpp"] = "#pragma once\n"
    write(classroom / "adversary", adversary)
    tampered = {"amplification.hpp", "rk4.hpp", "symplectic_euler.hpp", "spring_system.hpp", "implicit_euler.hpp",
                "pi_controller.hpp"}

    kit_files = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True).stdout.split()
    watched = [ROOT / f for f in kit_files if (ROOT / f).is_file()]
    before = {str(p): hashlib.sha1(p.read_bytes()).hexdigest() for p in watched}
    before_class = fingerprint([classroom])

    run = subprocess.run([str(ROOT / "kit"), "grade", "--out", str(out), "--timeout", "20",
                          *[str(classroom / n) for n in names]], cwd=ROOT, capture_output=True, text=True)
    print(run.stdout[-6000:])
    problems = [] if run.returncode == 0 else [f"./kit grade exited {run.returncode}: {run.stderr[-2000:]}"]

    def expect_row(name, passing, statuses=None):
        report = json.loads((out / name / "grade.json").read_text(encoding="utf-8"))
        expected_points = sum(value[i] for i in passing)
        if report["points"] != expected_points:
            problems.append(f"{name}: expected {expected_points}, got {report['points']}: "
                            + "; ".join(f"ex {r['id']} {r['status']} {r['message'][:100]}" for r in report["exercises"] if r["status"] != "pass"))
        for row in report["exercises"]:
            want = (statuses or {}).get(row["id"])
            if want and row["status"] not in want:
                problems.append(f"{name}: ex {row['id']}: expected {want}, got {row['status']}: {row['message'][:200]}")
        return report

    all_ids = set(value)
    by_file = {e["id"]: e["file"] for e in points["exercises"]}
    expect_row("complete", all_ids)
    expect_row("empty", set(), {i: ("compile error",) for i in all_ids})
    broken = expect_row("broken", all_ids - {"3.1"}, {"3.1": ("compile error",)})
    message = next(r["message"] for r in broken["exercises"] if r["id"] == "3.1")
    if not re.match(r"midpoint\.hpp:\d+:\d+: error", message):
        problems.append(f"broken: the compile error should name midpoint.hpp and its line, got: {message}")
    expect_row("segfaults", all_ids - {"2.2"}, {"2.2": ("crashed",)})
    expect_row("loops", all_ids - {"3.2"}, {"3.2": ("timeout",)})
    attacked = {i for i in all_ids if by_file[i] in tampered}
    report = expect_row("adversary", all_ids - attacked, {i: ("integrity", "compile error", "fail") for i in attacked})
    spawner = next(r for r in report["exercises"] if r["file"] == "pi_controller.hpp")
    if "start a process" not in spawner["message"]:
        problems.append(f"adversary: the spawning ex {spawner['id']} was not stopped by the sandbox: "
                        f"{spawner['status']}: {spawner['message'][:200]}")
    ignored = {path for path, _ in report["ignored"]}
    for shadow in (*CATCH_SHADOWS, "kit/state.hpp"):
        if shadow not in ignored:
            problems.append(f"adversary: {shadow} was not reported as ignored")

    with open(out / "class.csv", encoding="utf-8") as f:
        table = {row["submission"]: row for row in csv.DictReader(f)}
    for name in names:
        graded = json.loads((out / name / "grade.json").read_text(encoding="utf-8"))
        if name not in table or int(table[name]["total"]) != graded["points"]:
            problems.append(f"class.csv: row of {name} does not match its grade.json")
    if table.get("complete", {}).get("total") != str(total):
        problems.append("class.csv: the complete submission does not have full marks")

    # Regrading the same folders writes the same reports, byte for byte.
    reports_before = fingerprint_reports(out)
    again = subprocess.run([str(ROOT / "kit"), "grade", "--out", str(out), "--timeout", "20",
                            *[str(classroom / n) for n in names]], cwd=ROOT, capture_output=True, text=True)
    reports_after = fingerprint_reports(out)
    if again.returncode != 0 or reports_before != reports_after:
        changed_reports = sorted(k for k in reports_before if reports_before[k] != reports_after.get(k))
        problems.append(f"regrading changed the reports: {changed_reports} (exit {again.returncode})")

    after = {str(p): hashlib.sha1(p.read_bytes()).hexdigest() for p in watched}
    changed = [p for p in before if before[p] != after.get(p)]
    changed += [p for p in fingerprint([classroom]) if p not in before_class]
    changed += [p for p, h in before_class.items() if fingerprint([classroom]).get(p) != h]
    if (ROOT / "tests/grading/extra.cpp").exists():
        changed.append("tests/grading/extra.cpp was created")
    if any(outside.iterdir()):
        changed.append(f"{outside} has new files")
    for path, magic in shared_files.items():
        if not path.is_file() or not path.read_bytes().startswith(magic):
            changed.append(f"{path} (the batch's shared build) is missing or was overwritten")
    problems += [f"changed outside the grade trees: {c}" for c in changed]

    for p in problems:
        print(p, file=sys.stderr)
    print(f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
