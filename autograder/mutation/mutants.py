"""Mutants of a lab's solution files: one small, realistic change each.

A mutant changes one line of a student file of solutions/NN_name/student/, and
only a line the student writes (one that is not in the stub of
labs/NN_name/student/): given code is not what the grader checks. The rules are
the kinds of slip students make:

  relational   <  <=  >  >=  ==  !=  turned into a neighbour
  arithmetic   + and -, * and /, += and -=, *= and /= exchanged
  constant     a whole number +1 or -1, a real number x2 or /2
  min-max      min and max, floor and ceil exchanged
  swap-args    the two arguments of a call exchanged (not of a call whose order does not matter)
  drop-line    an assignment or a call statement removed
  normalize    normalize(x) becomes x
  swizzle      a GLSL swizzle's first two components exchanged (.xz -> .zx)

Lines that assert (STOA_ASSERT, assert) are left alone: they check the caller,
and no case calls with inputs they refuse. Each mutant is written as a .mistake file (the planted mistakes' format), so the
build makes it a program the way it makes a planted mistake one.
"""
import hashlib
import re
from dataclasses import dataclass
from pathlib import Path

GLSL_SUFFIXES = {".glsl", ".vert", ".frag", ".geom", ".comp"}
CPP_SUFFIXES = {".cpp", ".hpp", ".h"}

# Calls whose two arguments commute: exchanging them changes nothing.
COMMUTATIVE = {"dot", "min", "max", "distance", "std::min", "std::max", "glm::min", "glm::max", "glm::dot",
               "glm::distance", "equal", "notEqual", "std::swap", "std::hypot", "hypot"}
# First words of a line that declares rather than assigns or calls.
DECLARATION_WORDS = {"const", "constexpr", "static", "auto", "float", "double", "int", "unsigned", "bool", "uint",
                     "vec2", "vec3", "vec4", "mat3", "mat4", "ivec2", "ivec3", "uvec2", "std", "glm", "struct",
                     "return", "if", "for", "while", "else", "switch", "case", "break", "continue", "in", "out",
                     "uniform", "layout", "using", "namespace", "template", "typename", "size_t", "char", "void"}


# An assertion checks the caller, not the result: with the valid inputs every
# case gives, weakening or strengthening it changes nothing a case can see.
ASSERTION = re.compile(r"\b(STOA_ASSERT|assert|static_assert)\s*\(")


@dataclass
class Mutant:
    lab: str
    file: str          # the student file, relative to its student/ folder
    line: int          # 1-based, in the solution file
    rule: str
    find: str          # the solution's text, unique in the file
    replace: str       # the same text with the mutation
    function: str      # the function the line is in ("" when not known)

    @property
    def id(self):
        digest = hashlib.sha1(f"{self.file}\n{self.find}\n{self.replace}".encode()).hexdigest()[:8]
        stem = re.sub(r"[^A-Za-z0-9]", "_", Path(self.file).stem)
        return f"{stem}_{self.rule.replace('-', '_')}_{digest}"

    def mistake_text(self):
        return (f"hint: mutant {self.id} ({self.rule}) of {self.file}:{self.line}\n"
                f"file: {self.file}\n--- find\n{self.find}--- replace\n{self.replace}--- end\n")

    def diff(self):
        old = "".join("-" + line + "\n" for line in self.find.splitlines())
        new = "".join("+" + line + "\n" for line in self.replace.splitlines())
        return f"--- {self.lab}/{self.file}:{self.line} ({self.rule}, in {self.function or '?'})\n{old}{new}"


def code_part(line):
    """The line's code without a // comment, with string literals blanked (same length)."""
    blanked = re.sub(r'"(\\.|[^"\\])*"', lambda m: '"' + " " * (len(m.group(0)) - 2) + '"', line)
    at = blanked.find("//")
    return blanked if at < 0 else blanked[:at]


def code_lines(text):
    """Indices of the lines that hold code: not in a /* */ comment, not a preprocessor line."""
    inside = False
    result = []
    for index, line in enumerate(text.splitlines()):
        stripped = line.strip()
        if inside:
            if "*/" in stripped:
                inside = False
            continue
        if stripped.startswith("/*"):
            inside = "*/" not in stripped
            continue
        if not stripped or stripped.startswith("#") or stripped.startswith("//"):
            continue
        result.append(index)
    return result


def enclosing_functions(lines):
    """For each line, the name of the function whose body it is in (C++ and GLSL, by braces;
    a namespace's braces are not a function's)."""
    names = [""] * len(lines)
    signature = re.compile(r"^[\w:<>,\s\*&]*?\b([A-Za-z_]\w*(?:::\w+)*)\s*\([^;]*$")
    stack = []      # per open brace: the function it opens, "" for a block, None for a namespace
    pending = ""
    for index, line in enumerate(lines):
        code = code_part(line)
        in_function = any(entry for entry in stack if entry)
        if not in_function:
            stripped = code.lstrip()
            match = signature.match(code)
            if stripped.startswith("namespace"):
                pending = None
            elif match and not stripped.startswith(("if", "for", "while", "return")):
                pending = match.group(1)
        for char in code:
            if char == "{":
                in_function = any(entry for entry in stack if entry)
                stack.append("" if in_function else pending)
                pending = ""
            elif char == "}" and stack:
                stack.pop()
        names[index] = next((entry for entry in stack if entry), "")
    return names


def _operator_mutants(code):
    """(rule, start, end, replacement) for each operator that a rule changes."""
    swaps = {" < ": [" <= "], " <= ": [" < "], " > ": [" >= "], " >= ": [" > "], " == ": [" != "], " != ": [" == "]}
    for op, replacements in swaps.items():
        for match in re.finditer(re.escape(op), code):
            for replacement in replacements:
                yield "relational", match.start(), match.end(), replacement
    arithmetic = {" + ": " - ", " - ": " + ", " * ": " / ", " / ": " * ",
                  " += ": " -= ", " -= ": " += ", " *= ": " /= ", " /= ": " *= "}
    for op, replacement in arithmetic.items():
        for match in re.finditer(re.escape(op), code):
            yield "arithmetic", match.start(), match.end(), replacement


def _constant_mutants(code):
    number = re.compile(r"(?<![\w.])(\d+\.\d*|\.\d+|\d+)(f?)(?![\w.])")
    for match in number.finditer(code):
        text, suffix = match.group(1), match.group(2)
        if "." in text:
            value = float(text)
            if value == 0.0:
                continue
            for factor in (2.0, 0.5):
                new = repr(value * factor)
                if "e" in new:
                    continue
                yield "constant", match.start(), match.end(), new + suffix
        else:
            value = int(text)
            for new in (value + 1, value - 1):
                if new >= 0:
                    yield "constant", match.start(), match.end(), str(new) + suffix


def _word_mutants(code):
    pairs = {"min": "max", "max": "min", "floor": "ceil", "ceil": "floor"}
    for match in re.finditer(r"\b(min|max|floor|ceil)\s*\(", code):
        word = match.group(1)
        yield "min-max", match.start(1), match.end(1), pairs[word]


def _call_mutants(code, glsl):
    simple = r"\s*([\w.\[\]:]+(?:\s*[-+*/]\s*[\w.\[\]:]+)?)\s*"
    for match in re.finditer(r"([\w:]+)\(" + simple + "," + simple + r"\)", code):
        name = match.group(1)
        if name in COMMUTATIVE or match.group(2) == match.group(3):
            continue
        swapped = f"{name}({match.group(3)}, {match.group(2)})"
        yield "swap-args", match.start(), match.end(), swapped
    for match in re.finditer(r"\bnormalize\(", code):
        depth, end = 1, match.end()
        while end < len(code) and depth:
            depth += {"(": 1, ")": -1}.get(code[end], 0)
            end += 1
        if depth == 0:
            inner = code[match.end():end - 1]
            yield "normalize", match.start(), end, f"({inner})"
    if glsl:
        for match in re.finditer(r"\.([xyzw]{2,4}|[rgba]{2,4})\b", code):
            components = match.group(1)
            if components[0] == components[1]:
                continue
            permuted = components[1] + components[0] + components[2:]
            yield "swizzle", match.start(1), match.end(1), permuted


def _drop_line(line):
    code = code_part(line).strip()
    if not code.endswith(";") or code.count(";") != 1:
        return None
    first = re.match(r"[\w:]+", code)
    if not first or first.group(0) in DECLARATION_WORDS:
        return None
    # "Type name = ..." declares: two words before the '='.
    if re.match(r"^[\w:<>]+\s+[\w]+\s*(=|;|\[|\{)", code):
        return None
    indent = line[:len(line) - len(line.lstrip())]
    return indent + "// (removed by the mutant)"


def line_mutants(line, glsl):
    """(rule, new line) for every mutation of one line of code."""
    code = code_part(line)
    seen = set()
    found = []
    generators = [_operator_mutants(code), _constant_mutants(code), _word_mutants(code), _call_mutants(code, glsl)]
    for generator in generators:
        for rule, start, end, replacement in generator:
            new = line[:start] + replacement + line[end:]
            if new != line and new not in seen:
                seen.add(new)
                found.append((rule, new))
    dropped = _drop_line(line)
    if dropped is not None:
        found.append(("drop-line", dropped))
    return found


def unique_context(lines, index, new_line):
    """The smallest run of lines around `index` that occurs once in the file, and its mutated twin."""
    text = "\n".join(lines) + "\n"
    for before in range(0, 4):
        for after in range(0, 3):
            start, stop = max(0, index - before), min(len(lines), index + after + 1)
            find = "\n".join(lines[start:stop]) + "\n"
            if text.count(find) == 1:
                replaced = lines[start:index] + [new_line] + lines[index + 1:stop]
                return find, "\n".join(replaced) + "\n"
    return None


def mutants_of_file(lab, root, relative):
    """Every mutant of solutions/LAB/student/RELATIVE, on the lines its stub does not have."""
    solution = root / "solutions" / lab / "student" / relative
    stub = root / "labs" / lab / "student" / relative
    text = solution.read_text()
    lines = text.splitlines()
    given = {line.strip() for line in stub.read_text().splitlines()} if stub.exists() else set()
    glsl = solution.suffix in GLSL_SUFFIXES
    functions = enclosing_functions(lines)
    result = []
    for index in code_lines(text):
        if lines[index].strip() in given or ASSERTION.search(lines[index]):
            continue
        for rule, new_line in line_mutants(lines[index], glsl):
            context = unique_context(lines, index, new_line)
            if context:
                result.append(Mutant(lab, relative, index + 1, rule, context[0], context[1], functions[index]))
    return result


def mutants_of_lab(root, lab):
    folder = root / "solutions" / lab / "student"
    files = sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*")
                   if p.is_file() and p.suffix in GLSL_SUFFIXES | CPP_SUFFIXES)
    return [m for relative in files for m in mutants_of_file(lab, root, relative)]
