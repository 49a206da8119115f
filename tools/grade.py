#!/usr/bin/env python3
"""Score one graded build: read ctest's JUnit file and the build log, write grade.json,
grade.md and grade.junit.xml, and print the table. Called by `./kit grade`;
`grade.py summary REPORT.json...` prints the batch's one-line-per-folder summary.

An exercise scores its points when its test executable built and every test case in it
passed. Anything else scores 0, with the reason: did not compile, failed (first failing
check), crashed, or timed out.
"""
import argparse
import json
import pathlib
import re
import sys
import xml.etree.ElementTree as ET
from xml.sax.saxutils import escape


def compile_errors(build_log):
    """target name -> first compiler error line, from a `ninja -k 0` log."""
    errors, current = {}, None
    for line in build_log.splitlines():
        failed = re.match(r"FAILED: .*?(grade_ex[\w]+)", line)
        if failed:
            current = failed.group(1)
            continue
        if current and current not in errors and re.search(r"\berror\b", line):
            errors[current] = re.sub(r"^.*?/([^/]+:\d+:\d+: )", r"\1", line.strip())
    return errors


def first_failure(output):
    # The placeholder's own sentence says best what to do; Catch's compact reporter may put
    # it after the INFO text, so look for it first.
    placeholder = re.search(r"(ex \d+\.\d+ is not implemented yet[^'\n]*)", output)
    if placeholder:
        return placeholder.group(1)
    for line in output.splitlines():
        if "failed:" in line:
            return re.sub(r"^.*?([\w.-]+:\d+): failed: ", r"\1: ", line.strip())[:400]
    for line in output.splitlines():
        if line.strip():
            return line.strip()[:400]
    return ""


def ctest_outcomes(ctest_log):
    """test name -> ctest's verdict word (Passed, Failed, Timeout, Exception: SegFault, Not Run...).
    ctest's JUnit file leaves timeouts and crashes unnamed; its log names them."""
    outcomes = {}
    for match in re.finditer(r"Test\s+#\d+: (\S+) \.*\s*(?:\*{3})?([A-Za-z][^\n]*?)\s+[\d.]+ sec", ctest_log):
        outcomes[match.group(1)] = match.group(2).strip()
    return outcomes


def ctest_results(junit_path):
    if not junit_path.exists():
        return {}
    results = {}
    for case in ET.parse(junit_path).getroot().iter("testcase"):
        out = case.findtext("system-out") or ""
        results[case.get("name")] = {"status": case.get("status", ""), "time": float(case.get("time") or 0),
                                     "failure": case.find("failure") is not None, "output": out}
    return results


def grade(points, results, outcomes, build_log, configured):
    errors = compile_errors(build_log)
    rows = []
    for exercise in points["exercises"]:
        ident = exercise["id"]
        target = "grade_ex" + ident.replace(".", "_")
        result = results.get(f"grade.ex{ident}")
        verdict = outcomes.get(f"grade.ex{ident}", "")
        if not configured:
            status, message = "error", "the folder could not be configured as KIT_IMPL (see configure.log)"
        elif target in errors:
            status, message = "compile error", errors[target]
        elif result is None or result["status"] == "notrun":
            status, message = "not run", "the test executable was not built (see build.log)"
        elif result["status"] == "run" and not result["failure"]:
            status, message = "pass", ""
        else:
            out = result["output"]
            if verdict == "Timeout":
                status, message = "timeout", "did not finish within the time limit: an endless loop?"
            elif verdict.startswith("Exception") or "Child aborted" in verdict:
                status, message = "crashed", f"the test process died ({verdict}); {first_failure(out)}".rstrip("; ")
            else:
                status, message = "fail", first_failure(out)
        earned = exercise["points"] if status == "pass" else 0
        rows.append({"id": ident, "chapter": exercise["chapter"], "title": exercise["title"],
                     "file": exercise["file"], "points": earned, "max_points": exercise["points"],
                     "status": status, "message": message})
    return rows


def write_outputs(rows, label, out_dir):
    total = sum(r["points"] for r in rows)
    maximum = sum(r["max_points"] for r in rows)
    summary = {"submission": label, "folder": label, "points": total, "max_points": maximum, "exercises": rows}
    out_dir.mkdir(parents=True, exist_ok=True)
    (out_dir / "grade.json").write_text(json.dumps(summary, indent=2, ensure_ascii=False) + "\n", encoding="utf-8")
    md = [f"# Grade: {label}", "", f"**{total} / {maximum} points**", "",
          "| exercise | points | status | file | message |", "|---|---|---|---|---|"]
    for r in rows:
        msg = r["message"].replace("|", "\\|")
        md.append(f"| ex {r['id']}: {r['title']} | {r['points']} / {r['max_points']} | {r['status']} | {r['file']} | {msg} |")
    (out_dir / "grade.md").write_text("\n".join(md) + "\n", encoding="utf-8")
    failures = sum(r["status"] != "pass" for r in rows)
    xml = [f'<?xml version="1.0" encoding="UTF-8"?>',
           f'<testsuite name="{escape(label)}" tests="{len(rows)}" failures="{failures}">']
    for r in rows:
        name = escape(f"ex {r['id']}: {r['title']} ({r['max_points']} points)", {'"': "&quot;"})
        xml.append(f'  <testcase classname="{escape(r["chapter"])}" name="{name}">')
        if r["status"] != "pass":
            xml.append(f'    <failure message="{escape(r["status"], {chr(34): "&quot;"})}">{escape(r["message"])}</failure>')
        xml.append("  </testcase>")
    xml.append("</testsuite>")
    (out_dir / "grade.junit.xml").write_text("\n".join(xml) + "\n", encoding="utf-8")
    return total, maximum


def print_table(rows, label, total, maximum):
    print(f"\n{label}: {total} / {maximum} points")
    width = max(len(f"ex {r['id']} {r['title']}") for r in rows)
    for r in rows:
        name = f"ex {r['id']} {r['title']}"
        print(f"  {name:<{width}}  {r['points']:>3} / {r['max_points']:<3} {r['status']:<13} {r['message']}")


def batch_summary(reports):
    """One line per graded folder, for the end of a batch."""
    print("\nBatch summary (points, folder, report):")
    for report in reports:
        g = json.loads(pathlib.Path(report).read_text(encoding="utf-8"))
        print(f"  {g['points']:>4} / {g['max_points']:<4} {g['submission']:<24} {report}")


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "summary":
        batch_summary(sys.argv[2:])
        return 0
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--points", required=True, type=pathlib.Path)
    parser.add_argument("--junit", required=True, type=pathlib.Path)
    parser.add_argument("--build-log", required=True, type=pathlib.Path)
    parser.add_argument("--ctest-log", required=True, type=pathlib.Path)
    parser.add_argument("--configured", choices=("yes", "no"), default="yes")
    parser.add_argument("--label", required=True)
    parser.add_argument("--out", required=True, type=pathlib.Path)
    args = parser.parse_args()
    points = json.loads(args.points.read_text(encoding="utf-8"))
    build_log = args.build_log.read_text(encoding="utf-8", errors="replace") if args.build_log.exists() else ""
    ctest_log = args.ctest_log.read_text(encoding="utf-8", errors="replace") if args.ctest_log.exists() else ""
    rows = grade(points, ctest_results(args.junit), ctest_outcomes(ctest_log), build_log, args.configured == "yes")
    total, maximum = write_outputs(rows, args.label, args.out)
    print_table(rows, args.label, total, maximum)
    return 0


if __name__ == "__main__":
    sys.exit(main())
