"""The reports: grade.json, grade.md and grade.junit.xml per submission, the printed table, and
class.csv and class.md for a batch. They hold no time stamp and no timing, so regrading the same
inputs writes the same bytes."""
import collections
import csv
import io
import json
import pathlib
import re
from xml.sax.saxutils import escape

STATUSES = ("pass", "fail", "compile error", "crashed", "timeout", "integrity", "not run", "error")


CONTROL = re.compile(r"[\x00-\x08\x0b\x0c\x0e-\x1f]")  # not allowed in XML 1.0


def xml_text(text, quote=False):
    return escape(CONTROL.sub("?", text), {'"': "&quot;"} if quote else {})


def write_submission(report, out_dir):
    out_dir = pathlib.Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    rows, label = report["exercises"], report["submission"]
    _write(out_dir / "grade.json", json.dumps(report, indent=2, ensure_ascii=False) + "\n")
    md = [f"# Grade: {label}", "", f"**{report['points']} / {report['max_points']} points**", "",
          f"Seed {report['seed']}: the random cases of every exercise; `./kit grade --seed {report['seed']}` regrades "
          "with the same ones.", ""]
    if not report["sandboxed"]:
        md += ["**Not sandboxed** (graded with --no-sandbox): the student's code ran with the grader's rights.", ""]
    md += ["| exercise | points | status | file | message |", "|---|---|---|---|---|"]
    for r in rows:
        msg = r["message"].replace("|", "\\|")
        md.append(f"| ex {r['id']}: {r['title']} | {r['points']} / {r['max_points']} | {r['status']} | {r['file']} | {msg} |")
    if report["findings"]:
        md += ["", "## Static check", ""] + [f"- {f['file']}:{f['line']}: {f['severity']}: {f['what']}"
                                              for f in report["findings"]]
    if report["ignored"]:
        md += ["", "## Ignored files", ""] + [f"- {path}: {why}" for path, why in report["ignored"]]
    _write(out_dir / "grade.md", "\n".join(md) + "\n")
    failures = sum(r["status"] != "pass" for r in rows)
    xml = ['<?xml version="1.0" encoding="UTF-8"?>',
           f'<testsuite name="{xml_text(label, True)}" tests="{len(rows)}" failures="{failures}">']
    for r in rows:
        name = xml_text(f"ex {r['id']}: {r['title']} ({r['max_points']} points)", True)
        xml.append(f'  <testcase classname="{xml_text(r["chapter"], True)}" name="{name}">')
        if r["status"] != "pass":
            xml.append(f'    <failure message="{xml_text(r["status"], True)}">{xml_text(r["message"])}</failure>')
        xml.append("  </testcase>")
    xml.append("</testsuite>")
    _write(out_dir / "grade.junit.xml", "\n".join(xml) + "\n")


def _write(path, text):
    """Through a temporary name, so a report is whole or absent."""
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(text, encoding="utf-8")
    tmp.replace(path)


def print_table(report):
    rows = report["exercises"]
    sandbox = "" if report["sandboxed"] else "  (NOT sandboxed)"
    print(f"\n{report['submission']}: {report['points']} / {report['max_points']} points{sandbox}")
    width = max(len(f"ex {r['id']} {r['title']}") for r in rows)
    for r in rows:
        name = f"ex {r['id']} {r['title']}"
        print(f"  {name:<{width}}  {r['points']:>3} / {r['max_points']:<3} {r['status']:<13} {r['message']}")
    for f in report["findings"]:
        print(f"  static check: {f['file']}:{f['line']}: {f['severity']}: {f['what']}")


def load_reports(paths):
    """[(path, report or None, problem)]: a broken report is named, never fatal."""
    loaded = []
    for path in paths:
        try:
            report = json.loads(pathlib.Path(path).read_text(encoding="utf-8"))
            if not isinstance(report, dict) or "exercises" not in report:
                raise ValueError("no 'exercises' in it")
            loaded.append((str(path), report, ""))
        except (OSError, ValueError) as error:
            loaded.append((str(path), None, f"unreadable report: {error}"))
    return loaded


def write_class(points, loaded, out_dir, seed):
    """class.csv (a row per student, a column per exercise, a total) and class.md."""
    ids = [e["id"] for e in points["exercises"]]
    maximum = sum(e["points"] for e in points["exercises"])
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["submission"] + [f"ex {i}" for i in ids] + ["total", "max", "sandboxed", "problem"])
    statuses = {i: collections.Counter() for i in ids}
    earned = {i: [] for i in ids}
    causes = collections.Counter()
    for path, report, problem in sorted(loaded, key=lambda x: (x[1] or {}).get("submission", x[0])):
        if report is None:
            writer.writerow([path] + [""] * len(ids) + ["", maximum, "", problem])
            causes["unreadable report"] += 1
            continue
        by_id = {r["id"]: r for r in report["exercises"]}
        for i in ids:
            row = by_id.get(i, {"points": 0, "status": "not run"})
            statuses[i][row["status"]] += 1
            earned[i].append(row["points"])
            if row["status"] != "pass":
                causes[row["status"]] += 1
        writer.writerow([report["submission"]] + [by_id.get(i, {}).get("points", 0) for i in ids]
                        + [report["points"], report["max_points"], "yes" if report.get("sandboxed") else "no", ""])
    _write(pathlib.Path(out_dir) / "class.csv", buffer.getvalue())
    n = sum(1 for _, r, _ in loaded if r is not None)
    md = ["# Class report", "", f"{n} submissions graded" + (f", {len(loaded) - n} unreadable" if n < len(loaded) else "")
          + f", seed {seed} (`./kit grade --seed {seed}` regrades with the same cases)", "",
          "## Score per exercise", "", "| exercise | max | mean | " + " | ".join(STATUSES) + " |",
          "|---|---|---|" + "---|" * len(STATUSES)]
    for e in points["exercises"]:
        i = e["id"]
        mean = sum(earned[i]) / len(earned[i]) if earned[i] else 0.0
        md.append(f"| ex {i}: {e['title']} | {e['points']} | {mean:.2f} | "
                  + " | ".join(str(statuses[i][s]) for s in STATUSES) + " |")
    md += ["", "## Failures by cause", ""]
    md += [f"- {cause}: {count}" for cause, count in sorted(causes.items())] or ["- none"]
    _write(pathlib.Path(out_dir) / "class.md", "\n".join(md) + "\n")
