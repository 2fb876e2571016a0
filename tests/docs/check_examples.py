#!/usr/bin/env python3
"""Every example a page shows as runnable runs as written: the files
(docs/crowds-xml.md's worlds, docs/scene-files.md's scene) and the commands.

Each ```xml block whose root is <world> is saved beside the crowd assets (a copy
of assets/crowds/, where the pages say to save it) and run with
`stoa-crowds FILE --steps 60 --render PNG`; each ```json block that is a scene
file (it has "objects") beside the scene assets, with `stoa-editor FILE --render PNG`.
Each must exit 0 and draw a picture that is not blank (more than a handful of
colours). Each command line of a page (README.md and docs/) that runs a lab
program or tool on the tree's own files, `build/bin/labNN_name --list`,
`--list-checks`, `--check NAME`, `--render CASE --output FILE`, and
`build/bin/stoa-editor SCENE --render FILE`, runs from the repository root with
build/bin/ standing for BIN_DIR and its picture written elsewhere; it must exit 0.
Commands on a file of the reader's own (`my_world.xml`) are left out.

    check_examples.py SOURCE_DIR BIN_DIR     exit 0: every example runs; 1: which do not
"""
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "e2e"))
from check_ui_panel import read_png   # noqa: E402  (width, height, channels, rows)

BLOCK = re.compile(r"^```(xml|json)\n(.*?)^```", re.M | re.S)


def blocks(page):
    text = page.read_text()
    for match in BLOCK.finditer(text):
        line = text.count("\n", 0, match.start()) + 1
        yield match.group(1), match.group(2), line


def colours(png):
    """Distinct colours in an 8-bit RGB or RGBA PNG (the e2e tests' reader)."""
    _, _, channels, rows = read_png(png)
    return len({bytes(row[x:x + 3]) for row in rows for x in range(0, len(row), channels)})


COMMAND = re.compile(r"build/bin/(lab\d\d_[a-z_]+|stoa-editor|stoa-crowds) ([^#`|\n]*)")
READS_ONLY = re.compile(r"^(--list|--list-checks|--check \S+)$")
RENDERS = re.compile(r"^--render (\S+) --output (\S+)$")


def commands(source):
    """(where, program, arguments) of each runnable command line, once each."""
    seen = set()
    for page in [source / "README.md"] + sorted((source / "docs").rglob("*.md")):
        for number, line in enumerate(page.read_text().splitlines(), 1):
            for match in COMMAND.finditer(line):
                program, arguments = match.group(1), " ".join(match.group(2).split())
                if (program, arguments) in seen:
                    continue
                if program.startswith("lab") and (READS_ONLY.match(arguments) or RENDERS.match(arguments)):
                    pass
                elif program == "stoa-editor" and "--render" in arguments:
                    words = arguments.split()
                    scene = words[1] if words[0] == "--scene" else words[0]
                    if words[0] != "--scene" and not (source / "assets" / "scenes" / scene).exists():
                        continue   # the reader's own scene file
                else:
                    continue
                seen.add((program, arguments))
                yield f"{page.relative_to(source)}:{number}", program, arguments.split()


def run(command, cwd):
    try:
        done = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=300)
    except subprocess.TimeoutExpired:
        return 124, "timed out after 300 s"
    return done.returncode, (done.stdout + done.stderr).strip()


def main():
    if len(sys.argv) != 3:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    source, bin_dir = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
    problems, ran = [], 0
    with tempfile.TemporaryDirectory(prefix="stoa-doc-examples-") as work:
        work = pathlib.Path(work)
        crowds = work / "crowds"
        shutil.copytree(source / "assets" / "crowds", crowds)
        scenes = work / "scenes"
        shutil.copytree(source / "assets" / "scenes", scenes)
        for page in sorted((source / "docs").rglob("*.md")):
            for kind, text, line in blocks(page):
                where = f"{page.relative_to(source)}:{line}"
                if kind == "xml" and text.lstrip().startswith("<world"):
                    example = crowds / f"doc_example_{ran}.xml"
                    command = [str(bin_dir / "stoa-crowds"), str(example), "--steps", "60"]
                elif kind == "json" and '"objects"' in text:
                    example = scenes / f"doc_example_{ran}.json"
                    command = [str(bin_dir / "stoa-editor"), str(example), "--size", "320x180"]
                else:
                    continue
                ran += 1
                example.write_text(text)
                picture = work / f"example_{ran}.png"
                status, output = run(command + ["--render", str(picture), "--backend", "egl"], example.parent)
                if status != 0:
                    problems.append(f"{where}: the example does not run as written (exit {status}): {output[-400:]}")
                elif not picture.exists() or colours(picture) < 8:
                    problems.append(f"{where}: the example runs but draws a blank picture")
                else:
                    print(f"{where}: runs as written ({' '.join(pathlib.Path(c).name for c in command[:1])})")
        for where, program, arguments in commands(source):
            ran += 1
            words = list(arguments)
            for flag in ("--output", "--render"):   # pictures go to the work folder, not the tree
                if flag in words:
                    at = words.index(flag) + 1
                    if words[at].endswith(".png"):
                        words[at] = str(work / f"command_{ran}.png")
            status, output = run([str(bin_dir / program)] + words + ["--backend", "egl"]
                                 if "--render" in words or "--check" in words else [str(bin_dir / program)] + words,
                                 source)
            if status != 0:
                problems.append(f"{where}: `build/bin/{program} {' '.join(arguments)}` exits {status}: {output[-300:]}")
            else:
                print(f"{where}: build/bin/{program} {' '.join(arguments)}: runs as written")
    for problem in problems:
        print(problem)
    if problems:
        print(f"check_examples: {len(problems)} of {ran} examples do not run as written")
        return 1
    print(f"check_examples: all {ran} examples of the docs (files and commands) run as written")
    return 0


if __name__ == "__main__":
    sys.exit(main())
