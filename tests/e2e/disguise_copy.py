#!/usr/bin/env python3
"""disguise_copy.py rename-reorder|reformat SOURCE DEST STUB: a copied student
file, disguised as a student who copied it might disguise it, for the
similarity test (similarity_ranks_copies.sh).

  rename-reorder  every local name and parameter renamed (the functions the
                  stub defines keep their names, so the copy still fits the
                  lab), and the function definitions in the reverse order
  reformat        another layout: tabs, braces on their own lines, spaces
                  inside parentheses, a comment before each function

STUB is the lab's stub of the same file: its function names are kept.
"""
import re
import sys

KEYWORDS = set("""auto bool break case char class const constexpr continue default delete do double else enum
explicit false float for if inline int long namespace new nullptr operator private protected public return short
signed sizeof static struct switch template this true typedef typename unsigned using virtual void volatile while
vec2 vec3 vec4 mat3 mat4 uniform in out inout""".split())
DECLARED = re.compile(r"\b(?:const\s+)?(?:auto|bool|char|int|float|double|std::size_t|size_t|vec[234]|mat[34]|"
                      r"glm::\w+|std::[\w:]+(?:<[^;=(){}]*>)?)\s*[&*]?\s+(\w+)\s*(?=[=({;,:)\[])")
FUNCTION_START = re.compile(r"^[A-Za-z_][\w:<>,\s*&]*[\s*&]([\w:~]+)\(")


def function_names(stub_text):
    return {match.group(1).split("::")[-1] for line in stub_text.splitlines()
            if (match := FUNCTION_START.match(line))}


def rename(text, keep):
    names = {name for name in DECLARED.findall(text) if name not in keep and name not in KEYWORDS and len(name) > 0}
    for name in sorted(names, key=len, reverse=True):
        text = re.sub(r"(?<![\w.:])" + re.escape(name) + r"\b", "q_" + name[::-1], text)
    return text


def function_spans(lines):
    """(first, last) line indices of each definition at column 0: 'TYPE name(...) {' ... '}'."""
    spans, at = [], 0
    while at < len(lines):
        line = lines[at]
        if FUNCTION_START.match(line) and not line.startswith(("namespace", "struct", "class", "return")):
            if line.rstrip().endswith("}") and "{" in line:
                spans.append((at, at))
            elif line.rstrip().endswith("{") or (at + 1 < len(lines) and lines[at + 1].startswith("{")):
                end = at + 1
                while end < len(lines) and not lines[end].startswith("}"):
                    end += 1
                spans.append((at, end))
                at = end
        at += 1
    return spans


def reorder(text):
    lines = text.split("\n")
    spans = function_spans(lines)
    blocks = [lines[first:last + 1] for first, last in spans]
    out, at = [], 0
    for (first, last), block in zip(spans, reversed(blocks)):
        out += lines[at:first] + block
        at = last + 1
    return "\n".join(out + lines[at:])


def reformat(text):
    out, depth = [], 0
    for raw in text.split("\n"):
        line = raw.strip()
        if not line or line.startswith("#"):
            out.append(line)
            continue
        if line.startswith("}"):
            depth = max(0, depth - 1)
        code = line if line.startswith("//") else re.sub(r"\(\s*", "( ", re.sub(r"\s*\)", " )", line))
        if FUNCTION_START.match(line) and depth == 1 or (FUNCTION_START.match(line) and depth == 0):
            out.append("\t" * depth + "// --- " + code.split("(")[0].split()[-1] + " ---")
        if code.endswith("{") and code != "{" and not code.startswith("//"):
            out.append("\t" * depth + code[:-1].rstrip())
            out.append("\t" * depth + "{")
        else:
            out.append("\t" * depth + code)
        depth += line.count("{") - line.count("}") + (1 if line.startswith("}") else 0)
        depth = max(0, depth)
    return "\n".join(out)


def main():
    mode, source, dest, stub = sys.argv[1:5]
    text = open(source).read()
    keep = function_names(open(stub).read())
    if mode == "rename-reorder":
        text = reorder(rename(text, keep))
    elif mode == "reformat":
        text = reformat(text)
    else:
        raise SystemExit(f"disguise_copy.py: unknown mode {mode}")
    open(dest, "w").write(text)


if __name__ == "__main__":
    main()
