#!/usr/bin/env python3
"""check_docs.py SOURCE_DIR

Checks that the docs hold together with the code and the grader's galleries:

1. No source is named by a seed label ("seed 002", "the editor paper"): in docs/, labs/, shaders/,
   framework/ and the galleries' mistake.txt files.
2. Every "Author (year)", "Author et al. (year)" or "Author and Author (year)" citation in docs/ has
   its entry in docs/references.md, and docs/references.md is in the site's nav (mkdocs.yml).
3. Each lab page's pictures show what their captions say, from where the grader keeps them (the
   site copies them in: docs/hooks/reference_pictures.py): "Reference picture of case X" is
   autograder/references/NN/X.png; a mistake's picture "..., case X" is the gallery's
   autograder/references/NN/mistakes/M/X.png, of a case the gallery says M fails; every picture
   exists and has the size of its case (cases.ini).
4. Each "Common mistakes" section's "Fails:" line lists exactly the cases the gallery says that
   mistake fails (autograder/references/NN/mistakes/M/mistake.txt, written by
   `stoa-grade --update-references` from the measured runs; for a mistake that fails property
   checks only, its .mistake file), or says "every case" when it fails every picture case; and
   every planted mistake has its section.
5. Every lab folder with a cases.ini has its page docs/labs/NN_name.md, and the page is in the
   site's nav.

Prints every problem with its file and line; exits 1 when there is any.
"""

import re
import struct
import sys
from pathlib import Path

root = Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
problems = []


def problem(path, line, text):
    problems.append(f"{path.relative_to(root)}:{line}: {text}")


def text_files(*folders):
    for folder in folders:
        base = root / folder
        if not base.exists():
            continue
        for path in sorted(base.rglob("*")):
            if path.is_file() and path.suffix in {".md", ".cpp", ".hpp", ".glsl", ".vert", ".frag", ".ini", ".txt", ".h"}:
                yield path


# 1. Seed labels.
seed_label = re.compile(r"seed 00[0-9]|editor paper|teaching-engine paper", re.IGNORECASE)
for path in list(text_files("docs", "labs", "shaders", "framework")) + sorted(
        (root / "autograder" / "references").glob("*/mistakes/*/mistake.txt")):
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if seed_label.search(line):
            problem(path, number, f"a source named by a label, not by author and year: {line.strip()[:100]}")

# 2. Citations against docs/references.md.
references = root / "docs" / "references.md"
entries = set()
if not references.exists():
    problem(root / "docs", 0, "docs/references.md is missing")
else:
    for match in re.finditer(r"^- \*\*(.+?) \((\d{4})\)\.\*\*", references.read_text(encoding="utf-8"), re.M):
        entries.add((match.group(1), match.group(2)))
    if "references.md" not in (root / "mkdocs.yml").read_text(encoding="utf-8"):
        problem(root / "mkdocs.yml", 0, "docs/references.md is not in the site's nav")
name = r"[A-Z][\w'À-ž-]+"
citation = re.compile(rf"\b({name}(?: et al\.| and {name})?)(?: \(| )((?:19|20)\d\d)\)?")
entry_names = {author for author, _ in entries}
for path in text_files("docs"):
    if path == references:
        continue
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        for match in citation.finditer(line):
            author, year = match.group(1), match.group(2)
            # Only what looks like a citation: the name of an entry's first author.
            first = author.split(" ")[0]
            if not any(entry.split(" ")[0] == first for entry in entry_names):
                continue
            if (author, year) not in entries:
                problem(path, number, f"cites {author} ({year}), which docs/references.md does not list")


# 3 and 4. Lab pages against the cases and the galleries.
def png_size(path):
    with open(path, "rb") as file:
        header = file.read(24)
    if header[:8] != b"\x89PNG\r\n\x1a\n":
        return None
    return struct.unpack(">II", header[16:24])


def case_sizes(manifest):
    """The picture cases' sizes, and the names of the property checks (cases with `check =`)."""
    sizes, checks, current = {}, set(), None
    for line in manifest.read_text(encoding="utf-8").splitlines():
        section = re.match(r"\[case (\S+)\]", line.strip())
        if section:
            current = section.group(1)
            sizes[current] = (512, 512)
        elif current and re.match(r"resolution\s*=", line.strip()):
            width, height = line.split("=", 1)[1].split()
            sizes[current] = (int(width), int(height))
        elif current and re.match(r"check\s*=", line.strip()):
            checks.add(current)
    for name in checks:
        del sizes[name]
    return sizes, checks


def gallery(lab):
    """Each mistake's failed cases: from the gallery (autograder/references, in the release),
    and where the gallery has no entry (a mistake that fails property checks only, which have no
    picture) from its .mistake file in solutions/ when the tree has it."""
    mistakes = {}
    for info in sorted((root / "autograder" / "references" / lab / "mistakes").glob("*/mistake.txt")):
        for line in info.read_text(encoding="utf-8").splitlines():
            if line.startswith("fails:"):
                mistakes[info.parent.name] = line.split(":", 1)[1].split()
    for planted in sorted((root / "solutions" / lab / "mistakes").glob("*.mistake")):
        if planted.stem in mistakes:
            continue
        for line in planted.read_text(encoding="utf-8").splitlines():
            if line.startswith("fails:"):
                mistakes[planted.stem] = line.split(":", 1)[1].split()
    return mistakes


picture = re.compile(r"!\[([^\]]*)\]\(\.\./\.\./autograder/references/(\d\d_\w+)/"
                     r"(?:mistakes/([\w-]+)/)?([\w-]+)\.png\)")
old_picture = re.compile(r"!\[[^\]]*\]\([./]*images/\d\d_\w+/")
for page in sorted((root / "docs" / "labs").glob("[0-9][0-9]_*.md")):
    lab = page.stem
    manifest = root / "labs" / lab / "cases.ini"
    if not manifest.exists():
        continue
    sizes, checks = case_sizes(manifest)
    mistakes = gallery(lab)
    lines = page.read_text(encoding="utf-8").splitlines()
    for number, line in enumerate(lines, 1):
        if old_picture.search(line):
            problem(page, number, "a lab picture under docs/images/; link the reference itself, "
                                  f"../../autograder/references/{lab}/CASE.png (or mistakes/M/CASE.png)")
        for match in picture.finditer(line):
            caption, image_lab, mistake, stem = match.groups()
            image = root / "autograder" / "references" / image_lab / (f"mistakes/{mistake}" if mistake else "") / (stem + ".png")
            if image_lab != lab:
                problem(page, number, f"a picture of lab {image_lab} on the page of lab {lab}")
            named = re.search(r"case (\w+)\s*$", caption)
            if not named:
                problem(page, number, f"the caption '{caption}' does not name its case ('..., case NAME')")
                continue
            case_name = named.group(1)
            if case_name not in sizes:
                problem(page, number, f"the caption names case {case_name}, which labs/{lab}/cases.ini does not have"
                                      + (" as a picture case (it is a property check)" if case_name in checks else ""))
                continue
            if stem != case_name:
                problem(page, number, f"the caption says case {case_name} but the picture is {stem}.png")
            if mistake:
                fails = mistakes.get(mistake)
                if fails is None:
                    problem(page, number, f"picture of mistake {mistake}, which the gallery of {lab} does not have")
                elif fails and stem not in fails:
                    problem(page, number, f"the picture of mistake {mistake} shows case {stem}, which the gallery "
                                          f"says it does not fail (it fails {' '.join(fails)})")
            if not image.is_file():
                problem(page, number, f"{image.relative_to(root)} does not exist"
                                      + (" (stoa-grade --update-references writes it)" if mistake else ""))
            elif sizes.get(case_name) and png_size(image) != sizes[case_name]:
                problem(page, number, f"{image.relative_to(root)} is {png_size(image)}, "
                                      f"case {case_name} renders at {sizes[case_name]}")

    # "Fails:" lines, section by section under "## Common mistakes".
    in_mistakes, section_start, section = False, 0, []
    documented = set()

    def check_section(start, text_lines):
        text = " ".join(text_lines)
        # The mistake a section is about: its picture, or a "<!-- mistake: NAME -->" marker
        # where the picture is shown in the theory above.
        shown = [m.group(3) for m in picture.finditer(text) if m.group(3)]
        shown += re.findall(r"<!-- mistake: (\w+) -->", text)
        if not shown:
            return
        documented.add(shown[0])
        fails = mistakes.get(shown[0])
        if fails is None:
            return
        said = re.search(r"Fails(?::)?\s+(every case|(?:`\w+`(?:,\s*|\s+and\s+)?)+)", text)
        if not said:
            problem(page, start, f"the section of mistake {shown[0]} has no 'Fails:' line")
            return
        if said.group(1) == "every case":
            if set(fails) != set(sizes):
                problem(page, start, f"says mistake {shown[0]} fails every case; the gallery says it fails "
                                     f"{' '.join(fails)} (of {' '.join(sizes)})")
            return
        listed = re.findall(r"`(\w+)`", said.group(1))
        if set(listed) != set(fails):
            expected = "every case" if set(fails) == set(sizes) else ", ".join(f"`{c}`" for c in fails)
            problem(page, start, f"says mistake {shown[0]} fails {', '.join(listed)}; the gallery says: Fails: {expected}")

    for number, line in enumerate(lines, 1):
        if line.startswith("## "):
            if in_mistakes and section:
                check_section(section_start, section)
            in_mistakes = line.strip().lower() == "## common mistakes"
            section = []
        elif in_mistakes and line.startswith("### "):
            if section:
                check_section(section_start, section)
            section_start, section = number, [line]
        elif in_mistakes:
            section.append(line)
    if in_mistakes and section:
        check_section(section_start, section)
    for mistake in sorted(set(mistakes) - documented):
        problem(page, 0, f"the gallery's mistake {mistake} has no section under '## Common mistakes'")

# 5. Every lab has its page, and the page is in the site's nav.
nav = (root / "mkdocs.yml").read_text(encoding="utf-8") if (root / "mkdocs.yml").exists() else ""
for manifest in sorted((root / "labs").glob("[0-9][0-9]_*/cases.ini")):
    lab = manifest.parent.name
    page = root / "docs" / "labs" / f"{lab}.md"
    if not page.exists():
        problem(manifest, 0, f"lab {lab} has no page docs/labs/{lab}.md")
    elif f"labs/{lab}.md" not in nav:
        problem(page, 0, f"docs/labs/{lab}.md is not in mkdocs.yml's nav")

for line in problems:
    print(line)
if problems:
    print(f"check_docs: {len(problems)} problem(s)")
    sys.exit(1)
print("check_docs: the docs, the references, the pictures and the galleries agree")
