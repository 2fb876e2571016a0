#!/usr/bin/env python3
"""check_requirements.py SOURCE_DIR

Checks each lab page's requirement table (docs/labs/NN_name.md, "## What the grader checks")
against the lab's cases and its gallery of planted mistakes. A row is one rule the page states as
required:

    | Rule | Where | Fails without it | Planted mistake |
    |---|---|---|---|
    | Divide each plane by the length of its normal | [The frustum's planes](#the-frustums-planes) | `field_walk`, `boxes_only` | `planes_not_normalized` |

1. Every lab page has the section and its table, and every row fills all four columns.
2. "Where" links to sections of the same page that exist.
3. "Fails without it" names graded cases or property checks of labs/NN/cases.ini (the public
   ones: a student reads the table), at least one.
4. "Planted mistake" names mistakes of the lab's gallery (autograder/references/NN/mistakes, or
   solutions/NN/mistakes/*.mistake for one that fails property checks only), at least one; each
   case of the row is one the gallery measured a mistake of the row failing, so the row's claim
   is what the grader does, not what someone hoped.
5. Every planted mistake of the gallery is in some row: every pitfall the page warns of is a rule.
6. Every section of the page's theory that states a rule ("must", "never", "always", "required")
   is the "Where" of some row, or says why it is not with a `<!-- no rule: REASON -->` comment.

A rule that no case sees cannot be written into the table: the check fails until a case or check
catches it, with a planted mistake to prove it (issue 24's blind spots).

Prints every problem with its file and line; exits 1 when there is any.
"""

import re
import sys
from pathlib import Path

root = Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
problems = []

SECTION = "## What the grader checks"
HEADER = ["Rule", "Where", "Fails without it", "Planted mistake"]
# Sections that describe the lab rather than teach it: a "must" there is an instruction, not a rule.
NOT_THEORY = {"goal", "before you start", "the stubs", "run and grade", "the graded cases", "checks",
              "common mistakes", "other pitfalls", "going further", "what the grader checks",
              "writing your own world", "write your own cases", "your own cases"}
RULE_WORD = re.compile(r"\b(must|never|always|required)\b", re.IGNORECASE)


def problem(path, line, text):
    problems.append(f"{path.relative_to(root)}:{line}: {text}")


def anchor(title):
    """The id mkdocs (Python-Markdown's toc) gives a heading."""
    text = re.sub(r"`([^`]*)`", r"\1", title.strip()).lower()
    text = re.sub(r"[^\w\s-]", "", text)
    return re.sub(r"[-\s]+", "-", text).strip("-")


def public_cases(lab):
    names = set()
    manifest = root / "labs" / lab / "cases.ini"
    for line in manifest.read_text(encoding="utf-8").splitlines():
        match = re.match(r"\[case (\S+)\]", line.strip())
        if match:
            names.add(match.group(1))
    return names


def gallery(lab):
    """Each planted mistake's measured failed cases (the gallery's mistake.txt, written by
    stoa-grade --update-references); for one that fails property checks only, its .mistake file."""
    mistakes = {}
    for info in sorted((root / "autograder" / "references" / lab / "mistakes").glob("*/mistake.txt")):
        for line in info.read_text(encoding="utf-8").splitlines():
            if line.startswith("fails:"):
                mistakes[info.parent.name] = set(line.split(":", 1)[1].split())
    for planted in sorted((root / "solutions" / lab / "mistakes").glob("*.mistake")):
        if planted.stem in mistakes:
            continue
        for line in planted.read_text(encoding="utf-8").splitlines():
            if line.startswith("fails:"):
                mistakes[planted.stem] = set(line.split(":", 1)[1].split())
    return mistakes


def sections(lines):
    """(line number, level, title, anchor, prose lines) of every ## and ### heading: a section's
    own text, up to the next heading, without its code blocks."""
    found, current = [], None
    in_code = False
    for number, line in enumerate(lines, 1):
        if line.lstrip().startswith("```"):
            in_code = not in_code
            continue
        if not in_code and re.match(r"#{2,3} ", line):
            level = len(line) - len(line.lstrip("#"))
            title = line[level:].strip()
            current = [number, level, title, anchor(title), []]
            found.append(current)
        elif current and not in_code:
            current[4].append(line)
    return found


def cells(line):
    return [cell.strip() for cell in line.strip().strip("|").split("|")]


for page in sorted((root / "docs" / "labs").glob("[0-9][0-9]_*.md")):
    lab = page.stem
    if not (root / "labs" / lab / "cases.ini").exists():
        continue
    cases = public_cases(lab)
    mistakes = gallery(lab)
    lines = page.read_text(encoding="utf-8").splitlines()
    headings = sections(lines)
    anchors = {h[3] for h in headings}
    table_at = next((h for h in headings if h[2] == SECTION[3:]), None)
    if table_at is None:
        problem(page, 0, f"no '{SECTION}' section: every lab page lists its rules and the case that "
                         "fails without each (tests/docs/check_requirements.py)")
        continue

    # 1. The table.
    rows, header_seen = [], False
    for offset, line in enumerate(table_at[4]):
        number = table_at[0] + 1 + offset
        if not line.startswith("|"):
            if header_seen and rows:
                break
            continue
        row = cells(line)
        if not header_seen:
            header_seen = True
            if row != HEADER:
                problem(page, number, f"the table's columns are {row}; expected {HEADER}")
            continue
        if all(re.fullmatch(r":?-+:?", cell) for cell in row):
            continue
        rows.append((number, row))
    if not rows:
        problem(page, table_at[0], "the requirement table has no rows")

    covered_mistakes, covered_anchors = set(), set()
    for number, row in rows:
        if len(row) != 4 or not all(row):
            problem(page, number, "a row needs a rule, where the page teaches it, the cases that fail "
                                  "without it and the planted mistake that shows they do")
            continue
        rule, where, failing, planted = row
        # 2. Where.
        links = re.findall(r"\]\(#([\w-]+)\)", where)
        if not links:
            problem(page, number, f"'{rule[:50]}': 'Where' links to no section of the page")
        for link in links:
            if link not in anchors:
                problem(page, number, f"'{rule[:50]}': links to #{link}, which is no heading of this page")
            covered_anchors.add(link)
        # 3. The cases.
        named_cases = re.findall(r"`(\w+)`", failing)
        if not named_cases:
            problem(page, number, f"'{rule[:50]}': no case fails without it; add a case or a check that does")
        for case in named_cases:
            if case not in cases:
                problem(page, number, f"'{rule[:50]}': {case} is not a case of labs/{lab}/cases.ini")
        # 4. The planted mistakes, and that they fail what the row says.
        named_mistakes = re.findall(r"`(\w+)`", planted)
        if not named_mistakes:
            problem(page, number, f"'{rule[:50]}': no planted mistake shows that the cases catch it")
        measured = set()
        for mistake in named_mistakes:
            if mistake not in mistakes:
                problem(page, number, f"'{rule[:50]}': {mistake} is not a planted mistake of {lab}'s gallery")
                continue
            covered_mistakes.add(mistake)
            measured |= mistakes[mistake]
        for case in named_cases:
            if case in cases and named_mistakes and measured and case not in measured:
                problem(page, number, f"'{rule[:50]}': no mistake of the row fails {case} "
                                      f"(the gallery: {', '.join(sorted(measured))})")

    # 5. Every pitfall.
    for mistake in sorted(set(mistakes) - covered_mistakes):
        problem(page, table_at[0], f"the planted mistake {mistake} is in no row of the table")

    # 6. Every section that states a rule.
    top = None
    for number, level, title, slug, text in headings:
        if level == 2:
            top = title.lower()
        if top in NOT_THEORY or title.lower() in NOT_THEORY:
            continue
        if "<!-- no rule:" in "\n".join(text):
            continue
        stated = [line for line in text if RULE_WORD.search(line) and not line.lstrip().startswith("|")]
        if stated and slug not in covered_anchors:
            problem(page, number, f"section '{title}' states a rule ('{RULE_WORD.search(stated[0]).group(0)}': "
                                  f"{stated[0].strip()[:70]}) that no row of the table points to; add its row, "
                                  "or say why it is not one with <!-- no rule: REASON -->")

for line in problems:
    print(line)
if problems:
    print(f"check_requirements: {len(problems)} problem(s)")
    sys.exit(1)
print("check_requirements: every lab's stated rules fail a case without them, and the gallery shows it")
