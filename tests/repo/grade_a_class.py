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
                        classmate's file, the classmates' grade.json, the batch's judges and
                        programs, and every file of the program cache later batches take
                        programs from (build/grade-cache), where it also plants an entry
    rk4.hpp             std::_Exit(0) in a static initialiser (ctest would say "Passed")
    symplectic_euler.hpp  #define CHECK(...) to silence the checks, with a wrong method
    spring_system.hpp   #include of the kit's own solutions/ file, by absolute path
    implicit_euler.hpp  reads another submission's file
    pi_controller.hpp   starts processes from a static initialiser with posix_spawn (declared by
                        hand, so no header gives it away), as a fork bomb would: the sandbox
                        kills the test at the first one (bounded to 64 harmless processes, so
                        that a sandbox without the filter does not hurt the machine)
  and it ships a fake Catch2 (catch2/catch.hpp, catch2/catch_all.hpp, catch2/catch_test_macros.hpp,
  kit_catch.hpp) and kit/base/state.hpp (and its old path, kit/state.hpp) that would make every
  check pass.
  forger        solved, but with one attack per route that took full points from the grader that
                ran the graded test in the student's process:
    spring_system.hpp   a wrong method, and a forged record: a static initialiser writes a passing
                        record of every case to every descriptor and leaves, through ::write and
                        std::exit taken without a call
    midpoint.hpp        a wrong method, and an operator== against Catch's Approx, found by
                        argument-dependent lookup, that is always true
    rigid_quaternion_step.hpp  the kit's own quaternion rate (kit/rigid/rigid_integrators.hpp) does
                        the work, a header its exercise may not use
    rk4.hpp             a wrong method, and a forged record through <unistd.h>, which the check
                        forbids, included as <Eigen/../../unistd.h> (an allowed prefix)
  hog           solved, in a copy made before the library took its folders (every kit header at
                its old path, <kit/state.hpp>, which forwards to <kit/base/state.hpp>, and the old
                names Vector3, Matrix3, FemVector3 and SpriteRandom), but three
                files try to cost the class: a 256 MiB array in the object file
                (fem_strain.hpp) and an endless loop (cloth_pcg.hpp), each of which costs only its
                own exercise, and 4 MiB printed (sprite_over.hpp), which costs nothing: the output
                is cut at 1 MiB as it is written and 64 KiB of it is kept.
Checks: class.csv is right; every attacked item scores 0 (integrity, compile error or fail);
the untouched items still score; the compile error names the student's file and line;
regrading with the batch's seed writes the same reports byte for byte, taking every program the
first batch kept from the cache; --no-sandbox still grades the complete submission at full marks
and says so, and neither takes from nor adds to a cache; nothing outside the grade trees changed.

Usage: grade_a_class.py WORK_DIR
"""
import csv
import hashlib
import json
import os
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


def cache_counts(stderr, problems):
    """(programs taken from the cache, programs kept in it) as a batch reports them."""
    found = re.search(r"grade: (\d+) programs from earlier batches, (\d+) new kept", stderr)
    if not found:
        problems.append(f"a sandboxed batch did not report its use of the program cache: {stderr[-500:]}")
        return -1, -1
    return int(found.group(1)), int(found.group(2))


def old_names(name, text):
    """An exercise file as a copy made before kit/base/vec3.hpp and kit/base/random.hpp wrote it:
    the cloth's Vector3 and Matrix3, the element's FemVector3, the sprites' SpriteRandom."""
    if name.startswith("cloth_"):
        text = re.sub(r"\bMat3\b", "Matrix3", re.sub(r"\bVec3\b", "Vector3", text))
    elif name.startswith("fem_"):
        text = re.sub(r"\bVec3\b", "FemVector3", text)
    elif name.startswith("sprite_"):
        text = re.sub(r"\bRandom\b", "SpriteRandom", text).replace("<kit/random.hpp>", "<kit/sprite_random.hpp>")
    return text


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
    names = ["complete", "empty", "broken", "segfaults", "loops", "forger", "hog", "adversary"]

    write(classroom / "complete", solved)
    (classroom / "empty").mkdir(parents=True)
    write(classroom / "broken", dict(solved, **{"midpoint.hpp": solved["midpoint.hpp"].replace("return u + dt", "return u +* dt")}))
    write(classroom / "segfaults", dict(solved, **{"implicit_euler_spring.hpp": solved["implicit_euler_spring.hpp"].replace(
        "  const double k = spring.stiffness", "  *static_cast<volatile int*>(nullptr) = 1;\n  const double k = spring.stiffness")}))
    write(classroom / "loops", dict(solved, **{"rk4.hpp": solved["rk4.hpp"].replace(
        "  const auto h = dt / 2;", "  for (volatile int spin = 0;; spin = spin + 1) {}\n  const auto h = dt / 2;")}))

    classmates = [str(classroom / n / "explicit_euler.hpp") for n in names[:-1]]
    reports = [str(out / n / "grade.json") for n in names[:-1]]
    # What every classmate's grade goes through: the judges, the programs' loop, the batch's cache.
    judges = sorted((ROOT / "build" / "tests").glob("grade_ex*")) + [ROOT / "build/tests/libkit_remote_student.a"]
    shared = out / ".grading-shared"
    cache = ROOT / "build" / "grade-cache"  # the programs later batches, and other classes, take
    targets = [str(outside / "pwned"), str(ROOT / "tests/grading/points.json"), str(ROOT / "tests/grading/extra.cpp"),
               *map(str, judges[:2]), str(shared / "judges" / "grade_ex1_1"), str(shared / "programs" / "planted")]
    attack = ("inline const bool kit_attack = [] {\n"
              + "".join(f'  {{ std::ofstream f("{t}"); f << "{{}}"; }}\n' for t in targets + reports)
              + "".join(f'  {{ std::ofstream f("{c}", std::ios::app); f << "// tampered\\n"; }}\n' for c in classmates)
              + "  std::error_code e;\n"
              + f'  std::filesystem::create_directories("{cache / "planted"}", e);\n'
              + f'  {{ std::ofstream f("{cache / "planted" / "program"}"); f << "{{}}"; }}\n'
              + f'  for (const auto& p : std::filesystem::recursive_directory_iterator("{cache}", e))\n'
              + '    if (p.is_regular_file(e)) { std::ofstream f(p.path(), std::ios::app); f << "tampered"; }\n'
              + "  return true;\n}();\n")
    adversary = dict(solved)
    adversary["amplification.hpp"] = prepend(solved["amplification.hpp"].replace(
        "#include <complex>", "#include <complex>\n#include <filesystem>\n#include <fstream>"), attack)
    adversary["rk4.hpp"] = prepend(solved["rk4.hpp"].replace("#include <kit/base/not_implemented.hpp>", "#include <cstdlib>\n#include <kit/base/not_implemented.hpp>"),
                                   "inline const bool kit_quit = (std::_Exit(0), true);\n")
    adversary["symplectic_euler.hpp"] = solved["symplectic_euler.hpp"].replace(
        "#pragma once", "#pragma once\n#define CHECK(...) ((void)0)\n#define REQUIRE(...) ((void)0)").replace(
        "u.template tail<D>() + dt * accel", "u.template tail<D>() - dt * accel")
    adversary["spring_system.hpp"] = solved["spring_system.hpp"].replace(
        "#include <kit/problems/spring.hpp>", f'#include <kit/problems/spring.hpp>\n#include "{solutions / "spring_system.hpp"}"')
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
    adversary["kit/base/state.hpp"] = adversary["kit/state.hpp"] = "#pragma once\n"
    write(classroom / "adversary", adversary)

    expected = json.loads((ROOT / "tests/grading/expected_evidence.json").read_text(encoding="utf-8"))

    def forging(ids):
        """A static initialiser that writes a passing record of the exercises `ids` to every
        descriptor and leaves, through ::write and std::exit taken without a call."""
        cases = [(name, count) for i in ids for name, count in expected[i].items()]
        record = "".join(f"case\\t{name}\\t{count}\\t0\\n" for name, count in cases)
        record += f"end\\t{sum(count for _, count in cases)}\\t0\\n"
        return ("inline const bool kit_forged = [] {\n"
                "  auto out = ::write;\n"
                "  auto leave = std::exit;\n"
                f'  const char* record = "{record}";\n'
                "  std::size_t length = 0;\n"
                "  while (record[length]) ++length;\n"
                "  for (int fd = 3; fd < 256; ++fd) out(fd, record, length);\n"
                "  leave(0);\n"
                "  return true;\n"
                "}();\n")

    forger = dict(solved)
    # Route 1: ::write and std::exit are declared by what the graded test includes before the
    # student's file (Catch2, <cstdlib>), and taking them named no forbidden call.
    # The method is wrong (the damping's sign).
    forger["spring_system.hpp"] = prepend(solved["spring_system.hpp"].replace("-k, -c;", "-k, c;"), forging(["2.1"]))
    # Route 2: a wrong method, and an == found by argument-dependent lookup that beats Catch2's own
    # (Catch2 v2's Approx, Catch::Detail::Approx).
    forger["midpoint.hpp"] = solved["midpoint.hpp"].replace("#pragma once", (
        "#pragma once\nnamespace Catch { namespace Detail { class Approx;\n"
        "inline bool operator==(const double&, const Approx&) { return true; } } }")).replace("f(t + dt / 2", "f(t")
    # Route 3: the kit's own quaternion rate (rigid_integrators.hpp) does ex 8.2's work.
    forger["rigid_quaternion_step.hpp"] = (
        "#pragma once\n#include <kit/rigid/rigid_body.hpp>\n#include <kit/rigid/rigid_integrators.hpp>\nnamespace kit {\n"
        "inline Quat quaternion_step(const Quat& q, const Vec3& omega, double h) {\n"
        "  const Eigen::Vector4d y(q.w(), q.x(), q.y(), q.z());\n"
        "  const Eigen::Vector4d next = y + h * quaternion_rate(y, q.conjugate() * omega);\n"
        "  return Quat(next[0], next[1], next[2], next[3]).normalized();\n"
        "}\n}  // namespace kit\n")
    # Route 4: the static check's gaps: <unistd.h>, forbidden, reached through an allowed prefix
    # that climbs out (Eigen/../../unistd.h), for a forged record of a wrong ex 3.2.
    forger["rk4.hpp"] = prepend(solved["rk4.hpp"].replace("#pragma once", "#pragma once\n#include <Eigen/../../unistd.h>\n"
                                                          "#include <cstdlib>").replace(
                                    "(dt / 6) * (k1 + 2 * k2 + 2 * k3 + k4)", "dt * k2"),
                                forging(["3.2"]))
    write(classroom / "forger", forger)
    forged = {"spring_system.hpp", "midpoint.hpp", "rigid_quaternion_step.hpp", "rk4.hpp"}

    hog = {name: old_names(name, re.sub(r"#include <kit/\w+/(\w+\.hpp)>", r"#include <kit/\1>", text))
           for name, text in solved.items()}
    if hog == solved:
        sys.exit("FAILED: hog: no kit header to write at its old path")
    hog["fem_strain.hpp"] = prepend(hog["fem_strain.hpp"], "[[gnu::used]] static char kit_ballast[256 << 20] = {1};\n")
    hog["sprite_over.hpp"] = prepend(hog["sprite_over.hpp"].replace("#pragma once", "#pragma once\n#include <cstdio>"),
        "inline const bool kit_noise = [] {\n  for (int i = 0; i < (4 << 20); ++i) std::putchar('x');\n  return true;\n}();\n")
    hog["cloth_pcg.hpp"] = hog["cloth_pcg.hpp"].replace(
        "  const auto filtered = [&](Eigen::VectorXd w) {", "  for (volatile int spin = 0;; spin = spin + 1) {}\n  const auto filtered = [&](Eigen::VectorXd w) {", 1)
    write(classroom / "hog", hog)
    hogging = {"fem_strain.hpp", "cloth_pcg.hpp"}
    tampered = {"amplification.hpp", "rk4.hpp", "symplectic_euler.hpp", "spring_system.hpp", "implicit_euler.hpp",
                "pi_controller.hpp"}

    kit_files = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True).stdout.split()
    watched = [ROOT / f for f in kit_files if (ROOT / f).is_file()]
    before = {str(p): hashlib.sha1(p.read_bytes()).hexdigest() for p in watched}
    before_class = fingerprint([classroom])
    judge_digests = {j: hashlib.sha1(j.read_bytes()).hexdigest() for j in judges}

    cached_before = fingerprint([cache])
    run = subprocess.run([str(ROOT / "kit"), "grade", "--out", str(out), "--timeout", "20",
                          *[str(classroom / n) for n in names]], cwd=ROOT, capture_output=True, text=True)
    print(run.stdout[-6000:])
    problems = [] if run.returncode == 0 else [f"./kit grade exited {run.returncode}: {run.stderr[-2000:]}"]
    first_hits, first_kept = cache_counts(run.stderr, problems)

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
    expect_row("empty", set(), {i: ("fail",) for i in all_ids})  # graded as the placeholders
    broken = expect_row("broken", all_ids - {"3.1"}, {"3.1": ("compile error",)})
    message = next(r["message"] for r in broken["exercises"] if r["id"] == "3.1")
    if not re.match(r"midpoint\.hpp:\d+:\d+: error", message):
        problems.append(f"broken: the compile error should name midpoint.hpp and its line, got: {message}")
    expect_row("segfaults", all_ids - {"2.2"}, {"2.2": ("crashed",)})
    expect_row("loops", all_ids - {"3.2"}, {"3.2": ("timeout",)})
    for name, files in (("forger", forged), ("hog", hogging)):
        hit = {i for i in all_ids if by_file[i] in files}
        expect_row(name, all_ids - hit, {i: ("integrity", "compile error", "fail", "crashed", "timeout") for i in hit})
    noise = out / "hog" / "logs" / "ex5.3.printed"
    if not noise.is_file() or not 60_000 < noise.stat().st_size < 70_000:
        problems.append(f"hog: the 4 MiB printed by ex 5.3 should be kept as 64 KiB, got "
                        f"{noise.stat().st_size if noise.is_file() else 'nothing'}")
    attacked = {i for i in all_ids if by_file[i] in tampered}
    report = expect_row("adversary", all_ids - attacked, {i: ("integrity", "compile error", "fail") for i in attacked})
    spawner = next(r for r in report["exercises"] if r["file"] == "pi_controller.hpp")
    if "start a process" not in spawner["message"]:
        problems.append(f"adversary: the spawning ex {spawner['id']} was not stopped by the sandbox: "
                        f"{spawner['status']}: {spawner['message'][:200]}")
    ignored = {path for path, _ in report["ignored"]}
    for shadow in (*CATCH_SHADOWS, "kit/base/state.hpp"):
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

    # Regrading the same folders with the batch's seed writes the same reports, byte for byte.
    seed = json.loads((out / "complete" / "grade.json").read_text(encoding="utf-8"))["seed"]
    reports_before = fingerprint_reports(out)
    again = subprocess.run([str(ROOT / "kit"), "grade", "--out", str(out), "--timeout", "20", "--seed", seed,
                            *[str(classroom / n) for n in names]], cwd=ROOT, capture_output=True, text=True)
    reports_after = fingerprint_reports(out)
    if again.returncode != 0 or reports_before != reports_after:
        changed_reports = sorted(k for k in reports_before if reports_before[k] != reports_after.get(k))
        problems.append(f"regrading changed the reports: {changed_reports} (exit {again.returncode})")
    # ...though it compiled nothing that always compiles the same way: every program, and every
    # compiler error, came from the cache of the first batch (the same bytes, as above).
    hits, kept = cache_counts(again.stderr, problems)
    if (hits, kept) != (first_hits + first_kept, 0):
        problems.append(f"the regrade should take all {first_hits + first_kept} programs of the first batch from the "
                        f"cache and keep none anew; it took {hits} and kept {kept}")
    # No student's code reached the cache: what was there is untouched, nothing was planted.
    cached_after = fingerprint([cache])
    for path, sha in cached_before.items():
        if cached_after.get(path, sha) != sha:
            problems.append(f"{path} in the program cache was changed")
    if (cache / "planted").exists():
        problems.append(f"{cache / 'planted'} was planted in the program cache")

    # Without the sandbox the judges still decide, and every report says it was not sandboxed.
    # Unsandboxed, a student's program could rewrite the cache: such a batch neither uses nor feeds
    # it. Given a cache of its own that holds the complete submission's programs, it takes none
    # of them and adds nothing.
    bare_cache = work / "bare-cache"
    shutil.copytree(cache, bare_cache, ignore=shutil.ignore_patterns(".*"))
    bare_cached = fingerprint([bare_cache])
    bare = subprocess.run([str(ROOT / "kit"), "grade", "--no-sandbox", "--out", str(work / "bare"), "--cache",
                           str(bare_cache), str(classroom / "complete")], cwd=ROOT, capture_output=True, text=True)
    if "--no-sandbox: the programs of earlier batches are not used" not in bare.stderr:
        problems.append(f"--no-sandbox: the batch did not say it leaves the program cache alone: {bare.stderr[-500:]}")
    if "programs from earlier batches" in bare.stderr or fingerprint([bare_cache]) != bare_cached:
        problems.append("--no-sandbox: the batch used the program cache")
    bare_report = work / "bare" / "complete" / "grade.json"
    if bare.returncode != 0 or not bare_report.exists():
        problems.append(f"--no-sandbox: ./kit grade exited {bare.returncode}: {bare.stderr[-500:]}")
    else:
        graded = json.loads(bare_report.read_text(encoding="utf-8"))
        said = "Not sandboxed" in (work / "bare" / "complete" / "grade.md").read_text(encoding="utf-8")
        if graded["points"] != total or graded["sandboxed"] or not said:
            problems.append(f"--no-sandbox: {graded['points']} points, sandboxed {graded['sandboxed']}, "
                            f"grade.md says so: {said}")

    after = {str(p): hashlib.sha1(p.read_bytes()).hexdigest() for p in watched}
    changed = [p for p in before if before[p] != after.get(p)]
    changed += [p for p in fingerprint([classroom]) if p not in before_class]
    changed += [p for p, h in before_class.items() if fingerprint([classroom]).get(p) != h]
    if (ROOT / "tests/grading/extra.cpp").exists():
        changed.append("tests/grading/extra.cpp was created")
    if any(outside.iterdir()):
        changed.append(f"{outside} has new files")
    for judge, digest in judge_digests.items():
        if hashlib.sha1(judge.read_bytes()).hexdigest() != digest:
            changed.append(f"{judge} (a judge every classmate goes through) was overwritten")
    if shared.exists():
        changed.append(f"{shared} (the batch's programs) was left behind")
    problems += [f"changed outside the grade trees: {c}" for c in changed]

    for p in problems:
        print(p, file=sys.stderr)
    print(f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
