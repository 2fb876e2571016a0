#!/usr/bin/env python3
"""check_sizes.py SOURCE_DIR [--report]: the size rules of docs/framework.md
("House rules"), so that a file or function that grows past them is split by
concept rather than let grow:

  - no source file (C++, GLSL, Python, shell) outside tools/ and the lab apps
    (labs/NN_name/*, not their student/ folders) is over 600 lines;
  - no C++ function in framework/ or autograder/ is over 80 lines.

The exceptions, each with its reason, are in size_exceptions.txt beside this
script; an exception that no longer applies is an error too, so the list stays
true. --report prints every file over 400 lines and function over 50, largest
first (the figures in issue notes come from it).

Functions are found by their braces: a '{' whose statement head ends in ')'
(with const, noexcept, override, a trailing return type or a constructor's
initializer list after it) and is not a control statement or a lambda.
"""
import re
import sys
from pathlib import Path

FILE_LIMIT = 600
FUNCTION_LIMIT = 80
SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".glsl", ".vert", ".frag", ".py", ".sh"}
CONTROL = re.compile(r"^\s*(else\b|if\b|for\b|while\b|switch\b|do\b|try\b|catch\b|namespace\b|struct\b|class\b|"
                     r"union\b|enum\b|extern\b|return\b|case\b|TEST_CASE\b|SECTION\b)")
LAMBDA = re.compile(r"\]\s*(\([^{}]*\))?\s*(mutable\s*)?(noexcept\s*)?(->\s*[\w:<>,\s&*]+)?\s*$")
FUNCTION_HEAD = re.compile(r"\)\s*(const\s*)?(noexcept\s*)?((override|final)\s*)*(->\s*[\w:<>,\s&*]+)?\s*$")
NAME = re.compile(r"([~\w:]+(?:<[^()]*>)?|operator\s*\S+)\s*\(")


def without_comments_and_strings(text):
    """The text with comments removed and string/char literals emptied; newlines kept."""
    out, i, n = [], 0, len(text)
    while i < n:
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif text.startswith('R"', i) and re.match(r'R"([^(\s]*)\(', text[i:]):
            delimiter = re.match(r'R"([^(\s]*)\(', text[i:]).group(1)
            end = text.find(")" + delimiter + '"', i)
            j = n if end < 0 else end + len(delimiter) + 2
            out.append('""' + "\n" * text.count("\n", i, j))
            i = j
        elif text[i] in "\"'" and not (text[i] == "'" and i > 0 and text[i - 1].isalnum()):
            quote, j = text[i], i + 1
            while j < n and text[j] != quote and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(quote * 2)
            i = j + 1
        else:
            out.append(text[i])
            i += 1
    return "".join(out)


def functions(text):
    """(first line, line count, name) of each function body in C++ `text`."""
    code = without_comments_and_strings(text)
    stack, head, line, paren, found = [], "", 1, 0, []
    for ch in code:
        if ch == "\n":
            line += 1
            head += " "
            continue
        if ch == "(":
            paren += 1
        elif ch == ")":
            paren = max(0, paren - 1)
        if ch == "{":
            h = " ".join(head.split())
            is_function = bool(FUNCTION_HEAD.search(h)) and not CONTROL.match(h) and not LAMBDA.search(h)
            # A member's braced initializer in a constructor's list: the head goes on.
            initializer = bool(re.search(r"\)\s*:\s", h)) and bool(re.search(r"[\w>]\s*$", h)) and not CONTROL.match(h)
            name = ""
            if is_function:
                match = NAME.search(h)
                name = match.group(1) if match else h[-40:]
            stack.append((is_function, line, name, h if initializer else None))
            head = ""
        elif ch == "}":
            if stack:
                is_function, start, name, kept = stack.pop()
                if is_function:
                    found.append((start, line - start + 1, name))
                head = kept + "{}" if kept is not None else ""
        elif ch == ";" and paren == 0:
            head = ""
        else:
            head += ch
    return found


def is_lab_app(relative):
    parts = relative.parts
    return len(parts) >= 3 and parts[0] == "labs" and parts[2] != "student"


def tracked_sources(root):
    ignored = ("build", ".git", "site", "__pycache__")
    for path in sorted(root.rglob("*")):
        relative = path.relative_to(root)
        if any(part.startswith(ignored) for part in relative.parts) or not path.is_file():
            continue
        if path.suffix in SOURCE_SUFFIXES:
            yield path, relative


def read_exceptions(path):
    exceptions = {}
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        key, _, reason = line.partition(" -- ")
        if not reason.strip():
            raise SystemExit(f"{path}:{number}: expected 'WHAT -- why it is an exception', got: {line}")
        exceptions[key.strip()] = reason.strip()
    return exceptions


def measure(root):
    """(over-limit files, over-limit functions, every file size, every function size)."""
    files, long_functions, all_files, all_functions = [], [], [], []
    for path, relative in tracked_sources(root):
        text = path.read_text(encoding="utf-8", errors="replace")
        lines = text.count("\n") + (0 if text.endswith("\n") or not text else 1)
        all_files.append((lines, relative.as_posix()))
        if lines > FILE_LIMIT and relative.parts[0] != "tools" and not is_lab_app(relative):
            files.append(relative.as_posix())
        if relative.parts[0] in ("framework", "autograder") and path.suffix in (".cpp", ".hpp"):
            for start, count, name in functions(text):
                all_functions.append((count, f"{relative.as_posix()}:{start}", name))
                if count > FUNCTION_LIMIT:
                    long_functions.append(f"{relative.as_posix()} {name}")
    return files, long_functions, all_files, all_functions


def main(argv):
    if len(argv) < 2:
        print("usage: check_sizes.py SOURCE_DIR [--report]", file=sys.stderr)
        return 2
    root = Path(argv[1])
    files, long_functions, all_files, all_functions = measure(root)
    if "--report" in argv:
        print("files over 400 lines:")
        for lines, name in sorted(all_files, reverse=True):
            if lines > 400:
                print(f"  {lines:5d}  {name}")
        print("functions over 50 lines (framework/, autograder/):")
        for count, where, name in sorted(all_functions, reverse=True):
            if count > 50:
                print(f"  {count:5d}  {where}  {name}")
        return 0
    exceptions = read_exceptions(Path(__file__).with_name("size_exceptions.txt"))
    problems = []
    for name in files:
        if name not in exceptions:
            problems.append(f"{name}: over {FILE_LIMIT} lines; split it by concept (docs/framework.md, House rules)")
    for name in long_functions:
        if name not in exceptions:
            problems.append(f"{name}: a function over {FUNCTION_LIMIT} lines; split it")
    for name in exceptions:
        if name not in files and name not in long_functions:
            problems.append(f"size_exceptions.txt: '{name}' is within the limits now; take it off the list")
    for problem in problems:
        print(problem)
    if not problems:
        print(f"sizes within the limits ({len(exceptions)} listed exceptions)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
