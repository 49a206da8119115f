#!/usr/bin/env python3
"""A student sees their code work from the first exercise on: every chapter, built on a partly
solved copy of exercises/, runs every part whose exercises are written, prints the student's
results for those, and names each other part with the exercise it waits for.

Three trees:
  - "first": the first exercise of every chapter solved (1.1, 2.1, 3.1, 4.1, 5.1, …), and R(z) (2.4)
    without the symplectic step (2.3) it is drawn beside, and ω from L (8.3) with the step on R
    (8.1) it drives; the rest stubs;
  - "rest": the opposite;
  - "none": exercises/ as shipped, nothing solved.
The first two are built here, chapters only, as `./kit --impl DIR run` builds them (on the kit's
library built once). "none" is the student edition's own tree: repo.student-edition builds it
whole and checks it with --built, so that its chapters are compiled once, not twice.
Each chapter must exit 0 with figures on (12 frames of each animation), skip only parts whose
exercise is not solved, and report the numbers of the parts that are (checked against what the
lecture predicts).

Usage: partial_runs.py WORK_DIR [LIBKIT_COMMON]          "first" and "rest"
       partial_runs.py --built none BUILD_DIR WORK_DIR   "none", built in BUILD_DIR already
"""
import json
import math
import os
import pathlib
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))
import exercises  # noqa: E402

CHAPTERS = ["01-free-fall", "02-spring-stability", "03-rk2", "04-adaptive-rk", "05-sprites", "06-cloth-explicit",
            "07-cloth-implicit", "08-rigid-bodies", "09-continuum"]
FIRST = {"1.1", "2.1", "2.4", "3.1", "4.1", "5.1", "6.1", "6.2", "7.1", "8.1", "8.3", "9.1"}


def write_tree(path, solved):
    shutil.rmtree(path, ignore_errors=True)
    for rel, text in exercises.expected_tree(ROOT / "solutions", frozenset(solved)).items():
        target = path / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(text, encoding="utf-8")


def build(tree, build_dir, libraries):
    launcher = ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"] if shutil.which("ccache") else []
    subprocess.run(["cmake", "--preset", "release", "-B", str(build_dir), f"-DKIT_IMPL={tree}",
                    f"-DKIT_LIBRARIES={libraries}", *launcher],
                   cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    jobs = os.environ.get("KIT_JOBS", str(os.cpu_count() or 2))
    subprocess.run(["cmake", "--build", str(build_dir), "-j", jobs, "--target", *CHAPTERS], cwd=ROOT, check=True,
                   stdout=subprocess.DEVNULL)


def no_constant(name):
    raise ValueError(f"the summary holds {name}")


# Chapters 6 to 9 draw 12 frames of each scene, not 120 (their --frames counts pictures of a run
# of fixed length; chapter 5's sets the run's length): the animation is drawn all the same, and
# which parts run does not depend on how many pictures they take.
ANIMATED = {"06-cloth-explicit", "07-cloth-implicit", "08-rigid-bodies", "09-continuum"}


def run(build_dir, chapter, out):
    frames = ["--frames", "12"] if chapter in ANIMATED else []
    done = subprocess.run([str(build_dir / "bin" / chapter), "--json", "--out", str(out), *frames],
                          capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise AssertionError(f"{chapter}: exit {done.returncode}: {done.stderr.strip()[:400]}")
    return json.loads(done.stdout, parse_constant=no_constant)


def waits_for(summary):
    """{exercise id} named by the skipped parts."""
    ids = set()
    for entry in summary.get("skipped", []):
        reason = entry["reason"]
        assert reason.startswith("ex "), reason
        ids.add(reason.split()[1])
    return ids


def near(value, expected, tolerance):
    return isinstance(value, (int, float)) and math.isfinite(value) and abs(value - expected) <= tolerance


def expectations(tree):
    """{chapter: [(what, check(summary) -> bool)]}: the student's own numbers that must show."""
    if tree == "first":
        return {
            "01-free-fall": [
                ("explicit Euler (the loop, ex 1.1) in every sample, implicit '-'",
                 lambda s: all(isinstance(r["explicit"], float) and r["implicit"] is None and r["match"] is True
                               for r in s["samples"])),
                ("explicit Euler's orders 1 and 2, implicit's none",
                 lambda s: near(s["convergence"]["slopes"]["global_explicit"], 1, 0.01)
                 and near(s["convergence"]["slopes"]["local_explicit"], 2, 0.01)
                 and s["convergence"]["slopes"]["global_implicit"] is None),
                ("the round-off sweep of explicit Euler", lambda s: len(s["roundoff"]["explicit_double"]["dt"]) > 10),
            ],
            "02-spring-stability": [
                ("midpoint RK2 (ex 3.1) on the student's A and b (ex 2.1)",
                 lambda s: list(s["runs"]) == ["midpoint"] and s["runs"]["midpoint"]["status"] == "finished"),
                ("GSL on the student's A and b", lambda s: s["reference_max_gap"] < 1e-9),
                ("the spectral radius from R(z) (ex 2.4), beside the run's growth",
                 lambda s: near(s["runs"]["midpoint"]["spectral_radius"], (1 + 0.2 ** 4 / 4) ** 0.5, 1e-12)),
            ],
            "03-rk2": [
                ("midpoint RK2 exact on free fall", lambda s: s["free_fall"]["midpoint_relative_error"] < 1e-12),
                ("midpoint RK2 of order 2", lambda s: near(s["orders"]["midpoint"]["fitted"], 2, 0.05)),
            ],
            "04-adaptive-rk": [
                ("the guarded step doubling (ex 4.1) finishes",
                 lambda s: s["step_doubling"]["guarded"]["status"] == "finished"),
                ("step doubling in the work-precision diagram",
                 lambda s: "step doubling, Euler" in s["work_precision"]),
            ],
            "05-sprites": [
                ("the integrators priced against the closed form (kit code, no exercise)",
                 lambda s: near(s["integrators"]["midpoint"]["fitted_order"], 2, 0.05)),
                ("the scene waits for ex 5.2 (emission alone cannot run it)", lambda s: "counts" not in s),
                ("the student's emission (ex 5.1) measured against the fountain's spreads",
                 lambda s: near(s["emission"][0]["drawn_mean"], 6, 0.1)
                 and near(s["emission"][0]["drawn_half_width"], 0.6, 0.05)),
            ],
            "06-cloth-explicit": [
                ("the student's spring force (ex 6.1) checked", lambda s: s["spring"]["third"] < 1e-12),
                ("the student's network (ex 6.2) counted", lambda s: s["springs"]["total"] == s["springs"]["expected"]),
                ("the runs wait for the step (ex 6.3)", lambda s: "integrators" not in s and "stability" not in s),
            ],
            "07-cloth-implicit": [
                ("the student's Jacobian (ex 7.1) checked", lambda s: s["jacobian"]["fd"] < 1e-6),
                ("the system waits for ex 7.2, the runs for ex 6.3 and 7.3",
                 lambda s: "system" not in s and "stiffness" not in s and "run" not in s),
            ],
            "08-rigid-bodies": [
                ("the student's ω (ex 8.3) checked", lambda s: s["omega"]["error"] < 1e-14),
                ("Euler on R (ex 8.1) runs beside the kit's; the quaternion and the exponential map wait",
                 lambda s: set(s["integrators"]) == {"euler-R", "euler-R-polar", "midpoint", "rk4"}
                 and s["integrators"]["euler-R"]["flips"] == 8),
            ],
            "09-continuum": [
                ("the linear and springs plates on the student's F (ex 9.1); St Venant–Kirchhoff waits for ex 9.2",
                 lambda s: set(s["plate"]) == {"linear", "springs"}
                 and near(s["plate"]["linear"]["angle"], math.atan(math.pi), 1e-6)),
                ("the cantilever by linear FEM (ex 9.1) and springs (ex 6.1, 7.1) at order 2",
                 lambda s: {"linear", "springs"} <= set(s["cantilever"]) and "stvk" not in s["cantilever"]
                 and near(s["cantilever"]["linear"]["order"], 1.8, 0.2)),
            ],
        }
    if tree == "none":
        return {
            "01-free-fall": [("the exact heights and GSL's, every method '-'",
                              lambda s: all(r["explicit"] is None and r["reference"] > 0 for r in s["samples"]))],
            "02-spring-stability": [("no scheme run, the system described", lambda s: s["omega"] == 10)],
            "03-rk2": [("no scheme's order, and no empty figure drawn",
                        lambda s: not s.get("orders") and "convergence" in s["figures_waiting"])],
            "04-adaptive-rk": [("the kit's own DOPRI5 runs", lambda s: s["detail"]["rhs_evals"] == 985)],
            "05-sprites": [("the integrators' trade, and no frame", lambda s: near(
                s["integrators"]["euler"]["fitted_order"], 1, 0.05) and "contact_sheet" not in s.get("figures", {}))],
            "06-cloth-explicit": [("every figure waits", lambda s: {"stability", "energy", "mesh"}
                                   <= set(s.get("figures_waiting", [])) and not s.get("figures"))],
            "07-cloth-implicit": [("every figure waits", lambda s: {"stiffness", "damping", "trade-timing", "solver"}
                                   <= set(s.get("figures_waiting", [])) and not s.get("figures"))],
            "08-rigid-bodies": [("the kit's midpoint and RK4 flip 6 times, the drops run",
                                 lambda s: set(s["integrators"]) == {"midpoint", "rk4"}
                                 and s["integrators"]["rk4"]["flips"] == 6 and s["drop"]["bounces"] > 0)],
            "09-continuum": [("the material and Euler–Bernoulli's tip, nothing that needs F",
                              lambda s: near(s["material"]["tip"], 1.4715, 1e-9) and "plate" not in s)],
        }
    return {
        "01-free-fall": [
            ("both matrix forms (ex 1.2, 1.3) on the prediction, the loop '-'",
             lambda s: all(r["match"] is True and r["explicit_loop"] is None for r in s["samples"])),
            ("implicit Euler's orders 1 and 2", lambda s: near(s["convergence"]["slopes"]["global_implicit"], 1, 0.01)),
        ],
        "02-spring-stability": [
            ("implicit and symplectic Euler run without A and b",
             lambda s: {"implicit_euler", "symplectic_euler"} <= set(s["runs"])),
            ("implicit Euler keeps 1/sqrt(1 + (ω·Δt)²) of the amplitude a step (ex 2.2)",
             lambda s: all(near(r["per_step"], r["predicted_per_step"], 1e-12) for r in s["implicit_damping"])),
        ],
        "03-rk2": [
            ("free fall waits for ex 3.1 and ex 1.1", lambda s: s["free_fall"]["midpoint_relative_error"] is None),
            ("symplectic Euler of order 1", lambda s: near(s["orders"]["symplectic_euler"]["fitted"], 1, 0.05)),
        ],
        "04-adaptive-rk": [
            ("the student's Cash-Karp pair (ex 4.2, 4.3) in the work-precision diagram",
             lambda s: "Cash-Karp 5(4) (kit)" in s["work_precision"]),
        ],
        "05-sprites": [
            ("the emission and the scene wait for ex 5.1; the student's over compositing (ex 5.3) is taken",
             lambda s: "counts" not in s and "emission" not in s
             and not any("5.3" in e["reason"] for e in s.get("skipped", []))),
        ],
        "06-cloth-explicit": [
            ("without the network (ex 6.2) nothing runs past the spring force",
             lambda s: "spring" not in s and "springs" not in s and "integrators" not in s),
        ],
        "07-cloth-implicit": [
            ("without the Jacobian (ex 7.1) and the network (ex 6.2) nothing runs",
             lambda s: "jacobian" not in s and "system" not in s and "run" not in s),
        ],
        "08-rigid-bodies": [
            ("without ω from L (ex 8.3) the lecture's four wait, even with 8.2 and 8.4 written",
             lambda s: set(s["integrators"]) == {"midpoint", "rk4"} and "omega" not in s),
        ],
        "09-continuum": [
            ("without F (ex 9.1) every model waits, even with 9.2 and 9.3 written",
             lambda s: "plate" not in s and "cantilever" not in s and "turns" not in s
             and near(s["material"]["tip"], 1.4715, 1e-9)),
        ],
    }


def check_tree(tree, solved, build_dir, figures):
    """The problems of one built tree's chapters, each run with figures into figures/NN."""
    problems = []
    for chapter in CHAPTERS:
        try:
            summary = run(build_dir, chapter, figures / chapter)
        except (AssertionError, ValueError, subprocess.TimeoutExpired) as error:
            problems.append(f"{tree}: {error}")
            continue
        wrongly = waits_for(summary) & solved
        if wrongly:
            problems.append(f"{tree}: {chapter} skips parts waiting for exercises that are solved: {wrongly}")
        if not summary.get("skipped"):
            problems.append(f"{tree}: {chapter} names no part that waits (half the exercises are stubs)")
        if not list((figures / chapter).glob("*.png")) and not summary.get("figures_waiting"):
            problems.append(f"{tree}: {chapter} drew no figure, and names none that waits")
        for what, check in expectations(tree)[chapter]:
            try:
                ok = check(summary)
            except (KeyError, TypeError) as error:
                ok, what = False, f"{what} ({type(error).__name__}: {error})"
            print(f"{tree}: {chapter}: {'ok' if ok else 'MISSING'}: {what}")
            if not ok:
                problems.append(f"{tree}: {chapter}: {what}")
        print(f"{tree}: {chapter}: waits for {sorted(waits_for(summary))}")
    return problems


def main(argv):
    problems = []
    if len(argv) > 1 and argv[1] == "--built":
        if len(argv) != 5 or argv[2] != "none":
            sys.exit("usage: partial_runs.py --built none BUILD_DIR WORK_DIR")
        build_dir, work = pathlib.Path(argv[3]).resolve(), pathlib.Path(argv[4]).resolve()
        shutil.rmtree(work, ignore_errors=True)
        problems += check_tree("none", set(), build_dir, work / "none-figures")
    else:
        work = pathlib.Path(argv[1]).resolve()
        libraries = argv[2] if len(argv) > 2 else ""  # the test build's lib/ folder, or "" to compile them
        points = json.loads((ROOT / "tests/grading/points.json").read_text(encoding="utf-8"))["exercises"]
        every = {e["id"] for e in points}
        for tree, solved in [("first", FIRST), ("rest", every - FIRST)]:
            source, build_dir = work / tree, work / f"{tree}-build"
            write_tree(source, solved)
            build(source, build_dir, libraries)
            problems += check_tree(tree, solved, build_dir, work / f"{tree}-figures")
    for problem in problems:
        print("FAILED:", problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
