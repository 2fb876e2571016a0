#!/usr/bin/env python3
"""check_gl_calls.py FRAMEWORK_DIR: every OpenGL call the framework makes as a
statement of its own goes through STOA_GL_CALL(...) (stoa/gl/Debug.hpp), so that
checked mode (STOA_GL_CHECKED=1) names the call, its file and line. A call whose
value is used (glGetUniformLocation, glCheckFramebufferStatus, ...) is written
plainly and checked with STOA_GL_CHECK after it, which this does not police;
nor glDelete*, which destructors call (a check there could throw out of one).

Exempt: gl/Debug.cpp (the checker itself), gl/FunctionLoader.cpp and
app/HeadlessContext.cpp (before there is a context to check).

Prints FILE:LINE: the call, for each bare statement call; exit 1 when any.
"""
import re
import sys
from pathlib import Path

EXEMPT = {"gl/Debug.cpp", "gl/FunctionLoader.cpp", "app/HeadlessContext.cpp"}
# A statement that starts with a GL call: "glEnable(GL_BLEND);", possibly over several lines.
STATEMENT = re.compile(r"^\s*(?:else\s+|\}\s*else\s+)?(?:if\s*\(.*\)\s*)?(gl[A-Z]\w*)\s*\(")


def strip_comment(line):
    return line.split("//", 1)[0]


def bare_calls(path):
    found = []
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        code = strip_comment(line)
        match = STATEMENT.match(code)
        if match and "STOA_GL_CALL" not in code and not match.group(1).startswith("glDelete"):
            found.append((number, match.group(1)))
    return found


def main(argv):
    if len(argv) != 2:
        print("usage: check_gl_calls.py FRAMEWORK_DIR", file=sys.stderr)
        return 2
    source = Path(argv[1]) / "src"
    problems = []
    for path in sorted(source.rglob("*.cpp")):
        relative = path.relative_to(source).as_posix()
        if relative in EXEMPT:
            continue
        for number, call in bare_calls(path):
            problems.append(f"framework/src/{relative}:{number}: {call}(...) as a statement without STOA_GL_CALL "
                            "(stoa/gl/Debug.hpp): wrap it, so that checked mode can name it")
    for problem in problems:
        print(problem)
    if not problems:
        print("every GL call made as a statement goes through STOA_GL_CALL")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
