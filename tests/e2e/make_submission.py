#!/usr/bin/env python3
"""Makes a student's labs/ tree the way a student makes it: a copy of labs/ in
which every student file is its stub, with the solution's code pasted in.

    make_submission.py SOURCE DEST

SOURCE is a Stoa tree with labs/ and solutions/; DEST (absent or empty) becomes
the labs/ tree. The student files of a lab are the STUDENT_FILES of its
labs/NN_name/CMakeLists.txt. In each, the stub's includes, comments and layout
stay; the body of every stubbed function (C++ that throws stoa::NotImplemented,
GLSL that returns STOA_NOT_IMPLEMENTED, either marked TODO(labNN)) is replaced
by the body of the function of the same name in the solution's twin, and what
the solution adds around its functions (#includes, helpers, constants) is added
where the solution has it. The grading tests grade what this makes, so a stub
that includes its lab's header (03_meshes/student/normals.cpp includes lab03.hpp) is
graded as a student's would be.

It never writes a stub silently: a stubbed function without a twin in the
solution, a student file without one, or a stub left in the result is an error
naming the file and the function. Exit status 0 on success, 1 on such an error,
2 on bad usage.
"""

import difflib
import re
import shutil
import sys
from pathlib import Path

KEYWORDS_NOT_FUNCTIONS = {"namespace", "struct", "class", "union", "enum", "uniform", "layout", "buffer",
                          "in", "out", "extern", "if", "for", "while", "switch", "do", "else", "return"}
STUB_CODE = re.compile(r"\bthrow\s+(?:stoa::)?NotImplemented\s*\(|\bSTOA_NOT_IMPLEMENTED\s*\(")
STUB_MARK = re.compile(r"TODO\(lab\d+\)")


class SubmissionError(Exception):
    pass


def code_mask(text):
    """`text` with comments, string and character literals and preprocessor lines
    turned into spaces (newlines kept), so that braces and parentheses in what is
    left are code; positions are those of `text`."""
    out = list(text)
    i, n = 0, len(text)
    at_line_start = True
    while i < n:
        c = text[i]
        if at_line_start and c in " \t":
            i += 1
            continue
        if at_line_start and c == "#":
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out[i] = " "
                    i += 2
                    continue
                out[i] = " "
                i += 1
            continue
        at_line_start = False
        if text.startswith("//", i):
            while i < n and text[i] != "\n":
                out[i] = " "
                i += 1
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            for k in range(i, end):
                if out[k] != "\n":
                    out[k] = " "
            i = end
        elif c in "\"'":
            k = i + 1
            while k < n and text[k] != c and text[k] != "\n":
                k += 2 if text[k] == "\\" else 1
            for m in range(i + 1, min(k, n)):
                out[m] = " "
            i = k + 1
        else:
            if c == "\n":
                at_line_start = True
            i += 1
    return "".join(out)


def matching(mask, open_at, opening="{", closing="}"):
    depth = 0
    for i in range(open_at, len(mask)):
        if mask[i] == opening:
            depth += 1
        elif mask[i] == closing:
            depth -= 1
            if depth == 0:
                return i
    return -1


class Function:
    def __init__(self, name, parameters, line, open_at, close_at):
        self.name, self.parameters, self.line = name, parameters, line
        self.open_at, self.close_at = open_at, close_at   # the body's braces

    def key(self):
        return (self.name, self.parameters)


def function_header(header):
    """(name, normalized parameter list) of a function definition's header, or None."""
    words = re.findall(r"[A-Za-z_]\w*", header)
    if not words or words[0] in KEYWORDS_NOT_FUNCTIONS or "(" not in header:
        return None
    paren = header.index("(")
    if "=" in header[:paren]:
        return None   # an initializer, not a function
    name = re.search(r"([A-Za-z_~][\w:~]*)\s*$", header[:paren])
    close = matching(header, paren, "(", ")")
    if not name or close < 0:
        return None
    parameters = re.sub(r"\s+", " ", header[paren:close + 1])
    parameters = re.sub(r"\s*([(),&*<>:\[\]])\s*", r"\1", parameters)
    return name.group(1), parameters


def find_functions(text, where):
    """The function definitions at namespace level (not in classes), in order."""
    mask = code_mask(text)
    found = []

    def scan(begin, end):
        statement = begin
        i = begin
        while i < end:
            c = mask[i]
            if c in ";}":
                statement = i + 1
            elif c == "{":
                close = matching(mask, i)
                if close < 0:
                    raise SubmissionError(f"{where}:{text.count(chr(10), 0, i) + 1}: this {{ is never closed")
                header = mask[statement:i]
                if re.match(r"\s*(?:inline\s+)?namespace\b", header) or re.match(r'\s*extern\s*$', header):
                    scan(i + 1, close)
                else:
                    parsed = function_header(header)
                    if parsed:
                        line = text.count("\n", 0, i) + 1
                        found.append(Function(parsed[0], parsed[1], line, i, close))
                i = close
                statement = close + 1
            i += 1

    scan(0, len(mask))
    return found, mask


def is_stubbed(text, mask, function):
    body = slice(function.open_at, function.close_at + 1)
    return bool(STUB_CODE.search(mask[body]) or STUB_MARK.search(text[body]))


def twin_of(function, solution_functions, where_stub, where_solution):
    same = [f for f in solution_functions if f.key() == function.key()]
    if not same:
        same = [f for f in solution_functions if f.name == function.name]
    if len(same) != 1:
        problem = "has no twin" if not same else f"has {len(same)} functions of that name"
        raise SubmissionError(f"{where_stub}:{function.line}: the stubbed function {function.name}{function.parameters} "
                              f"{problem} in {where_solution}; the solution must define it once, so that its code "
                              "can be pasted in (a stub is never left in the submission)")
    return same[0]


def merge_around(stub, solution):
    """The stub (bodies already pasted in) with what only the solution has added
    where the solution has it; lines only the stub has (its comments, includes)
    stay."""
    a, b = stub.splitlines(keepends=True), solution.splitlines(keepends=True)
    merged = []
    for tag, i1, i2, j1, j2 in difflib.SequenceMatcher(None, a, b, autojunk=False).get_opcodes():
        if tag in ("equal", "delete"):
            merged += a[i1:i2]
        elif tag == "insert":
            merged += b[j1:j2]
        else:   # replace: the stub's lines, then the solution's
            merged += a[i1:i2] + b[j1:j2]
    return "".join(merged)


def paste_solution(stub_path, solution_path, where_stub, where_solution):
    """The stub with the solution's code pasted in; returns (text, pasted function names)."""
    stub = stub_path.read_text()
    solution = solution_path.read_text()
    stub_functions, stub_mask = find_functions(stub, where_stub)
    solution_functions, _ = find_functions(solution, where_solution)
    stubbed = [f for f in stub_functions if is_stubbed(stub, stub_mask, f)]
    if not stubbed:
        raise SubmissionError(f"{where_stub}: no stubbed function found (a function that throws NotImplemented, "
                              "returns STOA_NOT_IMPLEMENTED or is marked TODO(labNN)); is it a student file?")
    text = stub
    for function in reversed(stubbed):   # from the end, so earlier positions hold
        twin = twin_of(function, solution_functions, where_stub, where_solution)
        text = text[:function.open_at] + solution[twin.open_at:twin.close_at + 1] + text[function.close_at + 1:]
    text = merge_around(text, solution)

    left, left_mask = find_functions(text, where_stub)
    still = [f.name for f in left if is_stubbed(text, left_mask, f)]
    if still:
        raise SubmissionError(f"{where_stub}: still stubbed after pasting in {where_solution}: {', '.join(still)}")
    return text, [f.name for f in stubbed]


def student_files(lab_dir):
    cmake = lab_dir / "CMakeLists.txt"
    text = re.sub(r"#[^\n]*", "", cmake.read_text())
    call = re.search(r"stoa_add_lab\s*\((.*?)\)", text, re.S)
    if not call:
        raise SubmissionError(f"{cmake}: no stoa_add_lab(...) call")
    files, taking = [], False
    for word in call.group(1).split():
        if word in ("NAME", "STUDENT_FILES", "APP_SOURCES", "USES"):
            taking = word == "STUDENT_FILES"
        elif taking:
            files.append(word)
    if not files:
        raise SubmissionError(f"{cmake}: stoa_add_lab() lists no STUDENT_FILES")
    return files


def make_submission(source, dest):
    labs, solutions = source / "labs", source / "solutions"
    for folder in (labs, solutions):
        if not folder.is_dir():
            raise SubmissionError(f"{source} has no {folder.name}/ folder (a Stoa tree with its solutions is needed)")
    if dest.exists() and any(dest.iterdir()):
        raise SubmissionError(f"{dest} exists and is not empty")
    shutil.copytree(labs, dest, dirs_exist_ok=True)
    try:
        files, functions = fill_student_files(labs, solutions, dest)
    except SubmissionError:
        shutil.rmtree(dest, ignore_errors=True)   # no half-made submission to grade by mistake
        raise
    print(f"make_submission: {dest}: {files} student files, {functions} stubbed functions filled from solutions/")


def fill_student_files(labs, solutions, dest):
    files = functions = 0
    for lab_dir in sorted(p for p in labs.iterdir() if p.is_dir() and re.match(r"\d\d_", p.name)):
        if not (lab_dir / "CMakeLists.txt").is_file():
            continue
        for name in student_files(lab_dir):
            student = f"{lab_dir.name}/student/{name}"
            where_stub, where_solution = f"labs/{student}", f"solutions/{student}"
            if not (solutions / student).is_file():
                raise SubmissionError(f"{where_stub} has no twin {where_solution}")
            text, pasted = paste_solution(labs / student, solutions / student, where_stub, where_solution)
            (dest / student).write_text(text)
            files += 1
            functions += len(pasted)
    if files == 0:
        raise SubmissionError(f"{labs} has no lab folder with student files")
    return files, functions


def main(argv):
    if len(argv) != 3 or argv[1].startswith("-"):
        print("usage: make_submission.py SOURCE DEST", file=sys.stderr)
        return 2
    try:
        make_submission(Path(argv[1]).resolve(), Path(argv[2]).resolve())
    except SubmissionError as error:
        print(f"make_submission: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
