#!/usr/bin/env python3
"""check-release-paths.py RELEASE_DIR

Run by make-release.sh on the student release: every file that a page or comment a
student reads points at must be in the release. A student told to read
`tests/labs/NormalsTests.cpp` or to run `build/bin/stoa-tests-labs` in a release
that leaves them out is sent nowhere.

What is read: docs/ (but the instructor guide), labs/, shaders/, framework/
(sources, shaders, pages and manifests; not the build files), README.md and the
galleries' mistake.txt files (not their header comment, written for instructors). What counts as a pointer: a path
that starts with one of the tree's top-level folders and names a file (its last
part has an extension, e.g. `tests/labs/CascadesTests.cpp`, or is a pattern such as
`shaders/basic/headlight.*`), or a program under `build/bin/`. Placeholders match
anything: `NN_name`, `NN`, `<lab>`, `CASE`, `*`. A path is found when it exists from
the release's top or from the folder of the file that names it.

Prints each pointer that finds nothing, with its file and line; exits 1 when there is any.
"""

import glob
import re
import sys
from pathlib import Path

release = Path(sys.argv[1]).resolve()
top_folders = "tests|solutions|framework|labs|shaders|autograder|docs|assets|tools|build/bin"
pointer = re.compile(rf"(?<![\w./-])((?:{top_folders})/[A-Za-z0-9_.*<>{{}}/-]*[A-Za-z0-9_*>}}])")
placeholder = re.compile(r"NN_name|NN_\w+|\bNN\b|<[^>]*>|\bCASE\b|\bMISTAKE\b|\{[^}]*\}")
# The programs a build puts in build/bin/: the targets the release's CMake files add.
programs = set()
for cmake in list(release.rglob("CMakeLists.txt")) + list(release.rglob("*.cmake")):
    text = cmake.read_text(encoding="utf-8", errors="replace")
    programs.update(re.findall(r"(?:add_executable|stoa_add_test_program|stoa_add_tool)\(\s*([\w-]+)", text))
for lab in release.glob("labs/[0-9][0-9]_*"):
    programs.add("lab" + lab.name)


def readable_files():
    for folder in ("docs", "labs", "shaders", "framework"):
        for path in sorted((release / folder).rglob("*")):
            if not path.is_file() or path.name == "instructor-guide.md":
                continue
            if path.suffix in {".md", ".cpp", ".hpp", ".h", ".glsl", ".vert", ".frag", ".ini", ".txt"}:
                yield path
    if (release / "README.md").exists():
        yield release / "README.md"
    yield from sorted(release.glob("autograder/references/*/mistakes/*/mistake.txt"))


def found(path_text, base):
    if path_text.startswith("build/bin/"):
        parts = path_text[len("build/bin/"):].split("/")
        if len(parts) > 1:
            return True                             # a program in a track's folder (stubs/, mistakes/)
        return "*" in parts[0] or placeholder.search(parts[0]) is not None or parts[0] in programs
    last = path_text.rstrip("/").split("/")[-1]
    if "." not in last and "*" not in last:
        return True                                 # a folder: not checked
    pattern = placeholder.sub("*", path_text)
    # From the top, from the naming file's folder, and from docs/ (a gallery's
    # "docs: labs/02_shading.md#..." is a page of the docs site).
    for start in (release, base, release / "docs"):
        if glob.glob(str(start / pattern)):
            return True
    return False


problems = []
for path in readable_files():
    for number, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
        if path.name == "mistake.txt" and line.startswith("#"):
            continue                                # the instructors' "written from solutions/..." header
        for match in pointer.finditer(line):
            text = match.group(1).rstrip(".,;:")
            if not found(text, path.parent):
                problems.append(f"{path.relative_to(release)}:{number}: points at {text}, which the release does not have")

for problem in problems:
    print(problem)
if problems:
    sys.exit(1)
print(f"check-release-paths: every file the docs and comments point at is in the release")
