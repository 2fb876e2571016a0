#!/usr/bin/env python3
"""check_class_report.py WORK LAB MISTAKE MISSING_STATUS: the checks of
class_report.sh on what it left in WORK (out/, from-out/, export/, class.png).

class.json must say what gradebook.csv says: every student's points per lab and
total, and the histograms, means and medians computed here from the gradebook.
"""
import csv
import json
import os
import statistics
import sys

from png_file import pixel, read_png

BAR = (0x3A, 0x6F, 0xB0)   # the histogram bars' colour (ClassReportHtml.cpp, --bar)
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def bins_of(points, maximum):
    bins = [0] * 11
    for value in points:
        if maximum <= 0:
            bins[0] += 1
        elif value >= maximum - 1e-9:
            bins[10] += 1
        else:
            bins[min(9, max(0, int(value / maximum * 10 + 1e-9)))] += 1
    return bins


def check_distribution(name, distribution, points, maximum):
    check(abs(distribution["max_points"] - maximum) < 1e-9, f"{name}: max {distribution['max_points']} != {maximum}")
    check(abs(distribution["mean"] - statistics.mean(points)) < 1e-9,
          f"{name}: mean {distribution['mean']} != {statistics.mean(points)}")
    check(abs(distribution["median"] - statistics.median(points)) < 1e-9,
          f"{name}: median {distribution['median']} != {statistics.median(points)}")
    counts = [entry["count"] for entry in distribution["histogram"]]
    check(counts == bins_of(points, maximum), f"{name}: histogram {counts} != {bins_of(points, maximum)} from the gradebook")
    check(sum(counts) == len(points), f"{name}: the histogram counts {sum(counts)} students of {len(points)}")


def check_against_gradebook(out):
    rows = list(csv.DictReader(open(os.path.join(out, "gradebook.csv"))))
    labs = [column for column in rows[0] if column[:2].isdigit()]
    report = json.load(open(os.path.join(out, "class.json")))
    check(report["students"] == len(rows), f"class.json has {report['students']} students, the gradebook {len(rows)}")
    scores = {entry["student"]: entry for entry in report["scores"]}
    check(sorted(scores) == sorted(row["student"] for row in rows), "class.json and the gradebook name other students")
    for row in rows:
        entry = scores.get(row["student"], {})
        check(abs(entry.get("total", -1) - float(row["total"])) < 1e-9, f"{row['student']}: total {entry.get('total')} != {row['total']}")
        check(abs(entry.get("max", -1) - float(row["max"])) < 1e-9, f"{row['student']}: max {entry.get('max')} != {row['max']}")
        check(entry.get("status") == row["status"], f"{row['student']}: status {entry.get('status')} != {row['status']}")
        for lab in labs:
            check(abs(entry.get("labs", {}).get(lab, -1) - float(row[lab])) < 1e-9,
                  f"{row['student']}'s {lab}: {entry.get('labs', {}).get(lab)} != {row[lab]}")
    maximum = float(rows[0]["max"])
    check_distribution("overall", report["overall"], [float(row["total"]) for row in rows], maximum)
    for lab_report in report["labs"]:
        lab = lab_report["lab"]
        check_distribution(lab, lab_report, [float(row[lab]) for row in rows], lab_report["max_points"])
        for case in lab_report["cases"]:
            total = case["passed"] + case["failed"] + case["not_attempted"] + case["error"] + case["no_result"]
            check(total == len(rows), f"{lab}/{case['name']}: its counts add up to {total}, not {len(rows)}")
    return report, rows


def main():
    work, lab, mistake, missing_status = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
    out = os.path.join(work, "out")
    report, rows = check_against_gradebook(out)
    lab_report = next(entry for entry in report["labs"] if entry["lab"] == lab)

    # What to teach again: the mistake two students made comes first.
    first = report["teach_again"][0] if report["teach_again"] else {}
    check(first.get("kind") == "mistake" and first.get("name") == mistake and first.get("students") == ["dave", "erin"],
          f"the first thing to teach again is {first}, expected the mistake {mistake} of dave and erin")
    mistakes = {entry["name"]: entry["students"] for entry in lab_report["mistakes"]}
    check(mistakes.get(mistake) == ["dave", "erin"], f"{lab}'s mistakes: {mistakes}")
    not_compiled = {entry["student"]: entry["first_error"] for entry in lab_report["not_compiled"]}
    check(list(not_compiled) == ["carol"] and "error" in not_compiled.get("carol", ""),
          f"{lab}: did not compile: {not_compiled}")
    check(lab_report["not_attempted"] == ["bob"], f"{lab}: not attempted: {lab_report['not_attempted']}")
    check(any(case["failed"] >= 2 for case in lab_report["cases"]), "no case failed for dave and erin")

    html = open(os.path.join(out, "class.html"), encoding="utf-8").read()
    check("<script" not in html.lower(), "class.html has a script")
    check("<svg" in html and 'class="bar"' in html, "class.html draws no histogram")
    check('href="dave/report.html"' in html and os.path.isfile(os.path.join(out, "dave", "report.html")),
          "class.html does not link dave's report")
    check(not_compiled.get("carol", "").split(":")[0] in html, "class.html does not show carol's error")

    screenshot = os.path.join(work, "class.png")
    if os.path.exists(screenshot):
        image = read_png(screenshot)
        width, height = image[0], image[1]
        bar = sum(1 for y in range(height) for x in range(width)
                  if all(abs(a - b) <= 6 for a, b in zip(pixel(image, x, y), BAR)))
        print(f"screenshot {width}x{height}: {bar} pixels of the histograms' bars")
        check((width, height) == (1280, 900), f"screenshot size {width}x{height}")
        check(bar >= 1500, f"the screenshot's first screen shows {bar} pixels of histogram bars, expected a histogram")

    # --report-from the grading's own folder says what the run said.
    again = json.load(open(os.path.join(work, "from-out", "class.json")))
    check([(s["student"], s["total"], s["max"]) for s in again["scores"]] ==
          [(s["student"], s["total"], s["max"]) for s in report["scores"]],
          "--report-from on the grading's folder gives other scores")
    check(again["teach_again"][:1] == report["teach_again"][:1], "--report-from ranks something else first")
    check(os.path.isfile(os.path.join(work, "from-out", "class.html")), "--report-from wrote no class.html")
    # ... and from a Gradescope-like export, without the malformed file, which it names.
    exported = json.load(open(os.path.join(work, "export", "class.json")))
    check(exported["students"] == len(rows), f"the export's report has {exported['students']} students")
    check(len(exported["unreadable"]) == 1 and "mallory.json" in exported["unreadable"][0],
          f"the export's unreadable files: {exported['unreadable']}")
    export_err = open(os.path.join(work, "export.err")).read()
    check("mallory.json" in export_err, f"--report-from does not name the malformed file: {export_err!r}")
    missing_err = open(os.path.join(work, "missing.err")).read()
    check(missing_status == 1 and "no-such-folder" in missing_err,
          f"--report-from a missing folder: status {missing_status}, {missing_err!r}")

    for message in failures:
        print("FAIL:", message)
    print(open(os.path.join(out, "gradebook.csv")).read())
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
