#!/usr/bin/env python3
"""Valid input never ends in exit 1: every numeric flag of every chapter, with bad and extreme
values, ends in a reported result (exit 0, with a JSON summary) or a refusal (exit 2), within a
time bound.

For each flag (from the chapter's own `--flag-table`): -1, 0, NaN, ±Inf, 1e308, text, empty,
the two ends of its range (just inside an open end), one past them for whole numbers; then every
flag at its lower end at once, every flag at its upper end at once, and a fixed sample of pairs
of extremes. New chapters and new flags are covered with no extra work.

Each single-flag case runs as a person would, without --json, and writes its summary with
--summary FILE: on exit 0 the file holds one JSON object with no NaN or Infinity, and stdout no
nan or inf (whole words, any case: nan, -nan, inf, -inf, infinity); on exit 2 the message on
stderr names the flag and no summary file is left. A refused case is run again under --json (a
refusal costs nothing): the same exit code, and a message naming the flag. A valid case is not:
its one run already gives its text and its summary, and the runs of several flags (the lower
ends, the upper ends, the pairs) are made under --json.

A chapter with --quick (its fixed experiments at reduced sizes: chapters 6, 7 and 9) gets it in
every case but the two of all its flags at once: each flag still reaches every section, on the
same code, in a fraction of the time; the lower and upper ends together run the full sizes.

Usage: flag_table.py BIN_DIR [--seconds S]
"""
import concurrent.futures
import itertools
import json
import math
import pathlib
import random
import re
import subprocess
import sys
import tempfile

LIMIT = 1e300  # a range end beyond this is "no bound": its extremes are 1e308 and -1e308
NON_FINITE = re.compile(r"(?<![\w])[-+]?(nan|inf|infinity)(?![\w])", re.IGNORECASE)


def inside(value, is_open, toward):
    """A value just inside an open end of a range (toward +1 or -1)."""
    if not is_open:
        return value
    step = max(abs(value) * 1e-9, 1e-300)
    return value + toward * step


def ends(flag):
    """The extreme valid values of a flag, as command-line text."""
    if flag["kind"] == "count":
        return [str(int(flag["lo"])), str(int(flag["hi"]))]
    values = []
    if abs(flag["lo"]) < LIMIT:
        values.append(inside(flag["lo"], flag.get("lo_open"), +1))
    if abs(flag["hi"]) < LIMIT:
        values.append(inside(flag["hi"], flag.get("hi_open"), -1))
    if flag.get("nonzero") and flag["lo"] < 0 < flag["hi"]:
        values += [1e-300, -1e-300]
    return [repr(v) for v in values]


def singles(flag):
    values = ["-1", "0", "nan", "inf", "-inf", "1e308", "-1e308", "text", ""] + ends(flag)
    if flag["kind"] == "count":
        values += [str(int(flag["lo"]) - 1), str(int(flag["hi"]) + 1), "2.5"]
    return [[(flag["flag"], v)] for v in dict.fromkeys(values)]


def cases_for(table):
    """Every case, each as (flags, at_full_size): the lower and upper ends of all flags at once run
    the chapter's experiments at full size, the others may be --quick."""
    cases = [(c, False) for flag in table for c in singles(flag)]
    lows = [(f["flag"], ends(f)[0]) for f in table if ends(f)]
    highs = [(f["flag"], ends(f)[-1]) for f in table if ends(f)]
    cases += [(lows, True), (highs, True)]
    pairs = [[(a["flag"], x), (b["flag"], y)] for a, b in itertools.combinations(table, 2)
             for x in ends(a) for y in ends(b)]
    cases += [(pair, False) for pair in random.Random(20261122).sample(pairs, min(len(pairs), 8))]  # two extremes
    return cases


def run_once(binary, case, seconds, json_mode, summary=None, quick=False):
    """(exit code, stdout, stderr), or a problem (a string) when it did not end in time."""
    args = [str(binary), "--no-plot"] + (["--json"] if json_mode else []) + (["--summary", summary] if summary else [])
    args += ["--quick"] if quick else []
    for flag, value in case:
        args += [flag, value]
    try:
        done = subprocess.run(args, capture_output=True, text=True, timeout=seconds)
    except subprocess.TimeoutExpired:
        return f"still running after {seconds} s"
    return done.returncode, done.stdout, done.stderr


def summary_problem(text):
    """Why `text` is not one JSON summary free of NaN and Infinity, or None."""
    try:
        summary = json.loads(text)
    except ValueError:
        return f"not one JSON object: {text[:200]!r}"
    dumped = json.dumps(summary)
    return "the summary holds NaN or Infinity" if "NaN" in dumped or "Infinity" in dumped else None


def refusal_problems(name, err, single):
    """What is wrong with a refusal's message: none, or that it is empty or does not name `single`."""
    if not err.strip():
        return [f"{name}: exit 2 without a message"]
    if single and single not in err:
        return [f"{name}: exit 2, but the message does not name {single}: {err.strip()[:300]}"]
    return []


def run(binary, case, seconds, quick):
    """The problems of one case: a single flag's text run (and, refused, its --json run), or a
    run of several flags under --json. `quick`: the chapter's --quick is added."""
    words = " ".join(f"{f} {v!r}" for f, v in case) + (" --quick" if quick else "")
    name = f"{binary.name} {words}"
    single = case[0][0] if len(case) == 1 else None
    if not single:
        first = run_once(binary, case, seconds, json_mode=True, quick=quick)
        if isinstance(first, str):
            return [f"{name}: {first}"]
        code, out, err = first
        if code == 2:
            return refusal_problems(name, err, None)
        if code != 0:
            return [f"{name}: exit {code}: {err.strip()[:300]}"]
        why = summary_problem(out)
        return [f"{name}: exit 0 but stdout is {why}"] if why else []
    with tempfile.TemporaryDirectory() as folder:
        summary_file = pathlib.Path(folder) / "summary.json"
        first = run_once(binary, case, seconds, json_mode=False, summary=str(summary_file), quick=quick)
        if isinstance(first, str):
            return [f"{name} (text): {first}"]
        code, out, err = first
        written = summary_file.read_text() if summary_file.exists() else None
    problems = []
    if code == 2:
        if written is not None:
            problems.append(f"{name} (text): exit 2, yet a summary file was written")
        problems += refusal_problems(f"{name} (text)", err, single)
        second = run_once(binary, case, seconds, json_mode=True, quick=quick)
        if isinstance(second, str):
            return problems + [f"{name}: {second}"]
        json_code, _, json_err = second
        if json_code != 2:
            problems.append(f"{name}: exit {json_code} under --json, but 2 as text: {json_err.strip()[:300]}")
        else:
            problems += refusal_problems(name, json_err, single)
        return problems
    if code != 0:
        return [f"{name} (text): exit {code}: {err.strip()[:300]}"]
    why = summary_problem(written) if written is not None else "missing"
    if why:
        problems.append(f"{name} (text): exit 0 but the --summary file is {why}")
    found = NON_FINITE.search(out)
    if found:
        line = next(l for l in out.splitlines() if found.group(0) in l)
        problems.append(f"{name} (text): stdout prints {found.group(0)!r}: {line.strip()[:200]!r}")
    return problems


def main(argv):
    bin_dir = pathlib.Path(argv[1])
    seconds = float(argv[3]) if len(argv) > 3 and argv[2] == "--seconds" else 120.0
    binaries = sorted(p for p in bin_dir.iterdir() if p.is_file() and p.name[:2].isdigit())
    jobs = []
    for binary in binaries:
        table = json.loads(subprocess.run([str(binary), "--flag-table"], capture_output=True, text=True,
                                          check=True).stdout)
        has_quick = "--quick" in subprocess.run([str(binary), "--help"], capture_output=True, text=True,
                                                check=True).stdout
        jobs += [(binary, case, has_quick and not full_size) for case, full_size in cases_for(table)]
    problems = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for found in pool.map(lambda job: run(job[0], job[1], seconds, job[2]), jobs):
            for problem in found:
                problems.append(problem)
                print(problem, flush=True)
    singles = sum(1 for _, case, _ in jobs if len(case) == 1)
    quick = sum(1 for _, _, quick in jobs if quick)
    print(f"{len(jobs)} cases of {len(binaries)} chapters ({singles} of one flag, as text; {quick} with --quick); "
          f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
