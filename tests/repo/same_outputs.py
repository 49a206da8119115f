#!/usr/bin/env python3
"""What users see, as one fingerprint: shows that a change of the code's shape (files moved,
names changed, a formatter run) changed none of it.

Every chapter runs twice, with its defaults and with a set of other flags (its named choices away
from their defaults, and other values for its numbers), each with --json and its figures (PDF and
PNG). A run's fingerprint is its summary with timings left out, as chapters.reproducible-outputs
leaves them out (fields named with a unit of time, estimates), and the SHA-256 of every file it
wrote but those named "timing". Paths are written <kit> (the tree the chapters were built from)
and <out> (the run's folder), so trees in other folders compare. SOURCE_DATE_EPOCH is fixed, so
PDFs compare too.

  same_outputs.py record BIN_DIR FINGERPRINT [WORK_DIR]   before the change
  same_outputs.py check BIN_DIR FINGERPRINT [WORK_DIR]    after it: exit 0 only if every run is
                                                          the same, else each difference is named

WORK_DIR (default: a temporary folder) keeps the runs' files for a look at a difference.
"""
import concurrent.futures
import hashlib
import json
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

from chapter_binaries import chapter_binaries
from reproducible_outputs import without_timings

EPOCH = "1764288000"  # 2025-11-28 00:00 UTC: any fixed date; PDFs carry it
# Per chapter, flags other than the defaults: every named choice moved off its default, numbers
# changed, and the fixed experiments at --quick sizes where the chapter has them.
OTHER_FLAGS = {
    "01-free-fall": ["--x0", "50", "--v0", "3", "--g", "-3.7", "--dt", "0.05", "--t-end", "2"],
    "02-spring-stability": ["--mass", "2", "--stiffness", "50", "--damping", "0.3", "--dt", "0.02",
                            "--t-end", "20"],
    "03-rk2": ["--mass", "0.5", "--stiffness", "20", "--damping", "0.1", "--periods", "5",
               "--free-fall-steps", "500"],
    "04-adaptive-rk": ["--problem", "kepler", "--method", "cash-karp", "--rtol", "1e-8", "--atol", "1e-9",
                       "--eccentricity", "0.8", "--mu", "50"],
    "05-sprites": ["--scene", "snow", "--integrator", "midpoint", "--seed", "7", "--frames", "60",
                   "--width", "320", "--height", "240"],
    "06-cloth-explicit": ["--scene", "drape", "--integrator", "rk4", "--frames", "20", "--quick"],
    "07-cloth-implicit": ["--scene", "flag", "--integrator", "newton", "--solver", "mg", "--frames", "20",
                          "--quick"],
    "08-rigid-bodies": ["--body", "box", "--integrator", "exp-map", "--dt", "0.005", "--t-end", "5",
                        "--restitution", "0.3", "--friction", "0.5", "--frames", "30",
                        "--trade-steps", "1000"],
    "09-continuum": ["--model", "linear", "--mesh", "irregular", "--integrator", "implicit",
                     "--resolution", "8", "--young", "1e6", "--frames", "5", "--quick"],
}


def source_root(bin_dir):
    """The kit tree the chapters were built from (CMAKE_HOME_DIRECTORY of their build)."""
    for line in (bin_dir.parent / "CMakeCache.txt").read_text(encoding="utf-8").splitlines():
        if line.startswith("CMAKE_HOME_DIRECTORY:"):
            return line.split("=", 1)[1]
    sys.exit(f"{bin_dir.parent}/CMakeCache.txt names no source tree")


def neutral(data, root, out):
    """`data` (bytes or str) with the tree's and the run's folders written <kit> and <out>."""
    if isinstance(data, bytes):
        return data.replace(out.encode(), b"<out>").replace(root.encode(), b"<kit>")
    return data.replace(out, "<out>").replace(root, "<kit>")


def without_paths(value, root, out):
    if isinstance(value, dict):
        return {k: without_paths(v, root, out) for k, v in value.items()}
    if isinstance(value, list):
        return [without_paths(v, root, out) for v in value]
    return neutral(value, root, out) if isinstance(value, str) else value


def fingerprint(binary, flags, out_dir, root):
    """A run's summary (no timings, no paths) and its files' hashes, or the reason it failed."""
    shutil.rmtree(out_dir, ignore_errors=True)
    done = subprocess.run([str(binary), "--json", "--out", str(out_dir), *flags], capture_output=True,
                          text=True, env=dict(os.environ, SOURCE_DATE_EPOCH=EPOCH), timeout=1800)
    if done.returncode != 0:
        return {"failed": f"exit {done.returncode}: {done.stderr.strip()[:400]}"}
    out = str(out_dir.resolve())
    summary = without_paths(without_timings(json.loads(done.stdout), out_dir.resolve()), root, out)
    files = {str(p.relative_to(out_dir)): hashlib.sha256(neutral(p.read_bytes(), root, out)).hexdigest()
             for p in sorted(out_dir.rglob("*"))
             if p.is_file() and "timing" not in p.name}
    return {"summary": summary, "files": files}


def runs(bin_dir, work):
    binaries = chapter_binaries(bin_dir)
    root = source_root(bin_dir)
    jobs = [(b, name, flags) for b in binaries
            for name, flags in (("defaults", []), ("other flags", OTHER_FLAGS[b.name]))]
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        done = pool.map(lambda job: fingerprint(job[0], job[2], work / job[0].name / job[1].replace(" ", "-"),
                                                root), jobs)
        return {f"{b.name} {name}": {"flags": flags, **result}
                for (b, name, flags), result in zip(jobs, done)}


def differences(before, after):
    """What differs between two fingerprints of one run, one line each."""
    if "failed" in before or "failed" in after:
        return [f"failed: {after.get('failed') or before.get('failed')}"]
    found = []
    keys = sorted(k for k in set(before["summary"]) | set(after["summary"])
                  if before["summary"].get(k) != after["summary"].get(k))
    if keys:
        found.append(f"the summary differs under {keys}")
    a, b = before["files"], after["files"]
    if set(a) != set(b):
        found.append(f"only before: {sorted(set(a) - set(b))}; only after: {sorted(set(b) - set(a))}")
    changed = sorted(n for n in set(a) & set(b) if a[n] != b[n])
    if changed:
        found.append(f"{len(changed)} files differ: {changed[:12]}")
    return found


def main(argv):
    if len(argv) not in (4, 5) or argv[1] not in ("record", "check"):
        print(__doc__, file=sys.stderr)
        return 2
    mode, bin_dir, stored = argv[1], pathlib.Path(argv[2]).resolve(), pathlib.Path(argv[3])
    if not (bin_dir.parent / "CMakeCache.txt").is_file():
        print(f"BIN_DIR {bin_dir}: not the bin/ folder of a build (no CMakeCache.txt beside it)",
              file=sys.stderr)
        return 2
    if mode == "check" and not stored.is_file():
        print(f"FINGERPRINT {stored}: no such file (make it with `record` before the change)",
              file=sys.stderr)
        return 2
    if mode == "record" and not stored.parent.is_dir():
        print(f"FINGERPRINT {stored}: the folder {stored.parent} does not exist", file=sys.stderr)
        return 2
    with tempfile.TemporaryDirectory(prefix="same-outputs-") as scratch:
        work = pathlib.Path(argv[4] if len(argv) == 5 else scratch).resolve()
        now = runs(bin_dir, work)
    failed = [f"{name}: {run['failed']}" for name, run in now.items() if "failed" in run]
    if mode == "record":
        for line in failed:
            print("FAILED:", line)
        if failed:
            return 1
        stored.write_text(json.dumps(now, indent=1, sort_keys=True) + "\n", encoding="utf-8")
        files = sum(len(run["files"]) for run in now.values())
        print(f"{len(now)} runs, {files} files: fingerprint written to {stored}")
        return 0
    before = json.loads(stored.read_text(encoding="utf-8"))
    problems = []
    for name in sorted(set(before) | set(now)):
        if name not in before or name not in now:
            problems.append(f"{name}: {'new' if name in now else 'gone'}")
            continue
        if before[name]["flags"] != now[name]["flags"]:
            problems.append(f"{name}: recorded with other flags ({before[name]['flags']})")
            continue
        found = differences(before[name], now[name])
        verdict = "the same" if not found else "NOT the same"
        print(f"{name}: {len(now[name].get('files', {}))} files, {verdict}")
        problems += [f"{name}: {line}" for line in found]
    for line in problems:
        print("DIFFERS:", line)
    print(f"{len(now)} runs; {len(problems)} differences")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
