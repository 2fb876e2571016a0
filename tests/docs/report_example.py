#!/usr/bin/env python3
"""The student guide's report examples are what stoa-grade prints.

    report_example.py STOA_GRADE BUILD_DIR GUIDE.md [--write]

Each example in the guide follows a marker line
    <!-- report-example: ARGS -->
with ARGS the stoa-grade arguments ({build} is the build folder), and is the
```text block right after it. The script runs stoa-grade with them, puts the
work folder at /tmp/stoa-grade-k3Zp9q and the source tree at /home/you/stoa, and
compares: the lines must match, with runs of digits and of spaces each counted
as one (figures differ a little from one CPU to another). With --write it puts
the real output into the guide instead.
"""
import os
import re
import shlex
import subprocess
import sys
import tempfile

MARKER = re.compile(r"^<!-- report-example: (.*) -->\n```text\n(.*?)```\n", re.M | re.S)
SOURCE = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def run(stoa_grade, build, args):
    with tempfile.TemporaryDirectory() as work:
        argv = [stoa_grade] + [a.replace("{build}", build) for a in shlex.split(args)] + ["--work-dir", work]
        done = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, check=False)
        out = done.stdout.replace(os.path.realpath(work), "/tmp/stoa-grade-k3Zp9q").replace(work, "/tmp/stoa-grade-k3Zp9q")
    out = out.replace(SOURCE, "/home/you/stoa")
    return out.lstrip("\n")


def loose(text):
    return [re.sub(r" +", " ", re.sub(r"[0-9]+", "0", line)).rstrip() for line in text.splitlines()]


def main():
    stoa_grade, build, guide = sys.argv[1:4]
    write = "--write" in sys.argv[4:]
    text = open(guide, encoding="utf-8").read()
    examples = list(MARKER.finditer(text))
    if not examples:
        print(f"{guide}: no <!-- report-example: ... --> block")
        return 1
    failures = 0
    for match in reversed(examples):
        real = run(stoa_grade, build, match.group(1))
        if write:
            start, end = match.span(2)
            text = text[:start] + real + text[end:]
            continue
        want, got = loose(match.group(2)), loose(real)
        if want != got:
            failures += 1
            print(f"{guide}: the example after '<!-- report-example: {match.group(1)} -->' is not what stoa-grade prints")
            for i in range(max(len(want), len(got))):
                w = want[i] if i < len(want) else "<none>"
                g = got[i] if i < len(got) else "<none>"
                if w != g:
                    print(f"  line {i + 1}:\n    guide:  {w}\n    grader: {g}")
                    break
            print("  regenerate: python3 tests/docs/report_example.py BUILD/bin/stoa-grade BUILD docs/student-guide.md --write")
    if write:
        open(guide, "w", encoding="utf-8").write(text)
        print(f"wrote {len(examples)} examples into {guide}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
