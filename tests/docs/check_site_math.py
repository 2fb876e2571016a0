#!/usr/bin/env python3
"""check_site_math.py SITE_DIR SOURCE_DIR

Checks that the docs' equations reach a reader typeset, with no network (docs/hooks/mathjax.py):

1. The built site (mkdocs build into SITE_DIR): no page shows a raw "$$" or "$" outside code and
   outside the math elements arithmatex writes (<span class="arithmatex">\\(...\\)</span>,
   <div class="arithmatex">\\[...\\]</div>): a dollar left in the text is an equation that was not
   recognised, and that MathJax will not typeset either.
2. Every page with equations loads MathJax from the site itself, and the files MathJax loads for
   these pages are there (measured with chromium on the lab pages: the config, the CommonHTML
   output, the table layout, the operator table, the fonts).
3. No page loads a script or a style sheet from http(s):// or //host: the site must work offline.
   Every local script and style sheet a page names exists in the site.
4. The Markdown sources (SOURCE_DIR/docs): no equation holds a backslash before punctuation
   (\\, \\{ \\\\ ...), which GitHub's Markdown takes as an escape before its math renderer sees it
   (write \\thinspace, \\lbrace, \\cr instead), nor a _ after a bracket or a space, which it may take
   with a later _ for emphasis (\\hat{A}_1 = B_{1}); the page would read differently there.

Prints every problem with its page or file and line; exits 1 when there is any.
"""

import re
import sys
import unicodedata
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import urljoin, urlparse

if len(sys.argv) != 3:
    sys.exit(__doc__.split("\n\n")[0])
site = Path(sys.argv[1]).resolve()
source = Path(sys.argv[2]).resolve()
problems = []

MATHJAX = "mathjax"
# What chromium requested to typeset the lab pages (fonts without MathJax's installed locally).
MATHJAX_LOADS = [
    "MathJax.js",
    "jax/output/CommonHTML/jax.js",
    "jax/output/CommonHTML/autoload/mtable.js",
    "jax/output/CommonHTML/fonts/TeX/fontdata.js",
    "jax/output/CommonHTML/fonts/TeX/AMS-Regular.js",
    "jax/output/CommonHTML/fonts/TeX/SansSerif-Regular.js",
    "jax/output/CommonHTML/fonts/TeX/Typewriter-Regular.js",
    "jax/element/mml/optable/BasicLatin.js",
] + [f"fonts/HTML-CSS/TeX/woff/MathJax_{font}.woff" for font in (
    "Main-Regular", "Main-Italic", "Math-Italic", "SansSerif-Regular", "Typewriter-Regular",
    "Size1-Regular", "Size2-Regular", "Size3-Regular", "Size4-Regular")]


def punctuation(character):
    """CommonMark's punctuation, for its emphasis rules: Unicode punctuation and symbols."""
    return unicodedata.category(character).startswith(("P", "S"))


class Page(HTMLParser):
    """The text a reader sees outside code and math, and the scripts and style sheets a page loads."""

    skipped = {"script", "style", "code", "pre"}

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.open = []          # (tag, skipped) for every open element
        self.text = []          # (line, text) outside code and math
        self.loads = []         # (line, url) of scripts and style sheets
        self.math = 0

    def handle_starttag(self, tag, attrs):
        attributes = dict(attrs)
        if tag == "script" and attributes.get("src"):
            self.loads.append((self.getpos()[0], attributes["src"]))
        if tag == "link" and "stylesheet" in (attributes.get("rel") or "") and attributes.get("href"):
            self.loads.append((self.getpos()[0], attributes["href"]))
        if tag in {"link", "meta", "img", "br", "hr", "input", "source"}:
            return  # void elements never close
        is_math = "arithmatex" in (attributes.get("class") or "").split()
        self.math += is_math
        inside = bool(self.open and self.open[-1][1])
        self.open.append((tag, inside or is_math or tag in self.skipped))

    def handle_endtag(self, tag):
        if any(open_tag == tag for open_tag, _ in self.open):
            while self.open.pop()[0] != tag:
                pass

    def handle_data(self, data):
        if not (self.open and self.open[-1][1]):
            self.text.append((self.getpos()[0], data))


# 1-3. The built site.
pages = sorted(path for path in site.rglob("*.html") if MATHJAX not in path.relative_to(site).parts[:1])
if not pages:
    problems.append(f"{site}: no pages; build the site first (mkdocs build -d {site})")
pages_with_math = 0
for path in pages:
    name = path.relative_to(site)
    page = Page()
    page.feed(path.read_text(encoding="utf-8"))
    for line, text in page.text:
        for match in re.finditer(r"\$\$?", text):
            context = text[max(0, match.start() - 40):match.end() + 40].replace("\n", " ").strip()
            what = ("a display equation that arithmatex did not take ($$ on lines of their own, "
                    "a blank line before and after)" if match.group() == "$$" else
                    "an inline equation that arithmatex did not take (no space after the opening $ "
                    "or before the closing one), or a dollar outside code")
            problems.append(f"{name}:{line}: raw {match.group()} in the text, {what}: ...{context}...")
            break  # one report for each piece of text: its closing dollar would repeat it
    page_url = "http://site.invalid/" + path.relative_to(site).as_posix()
    mathjax = []
    for line, url in page.loads:
        parsed = urlparse(url)
        if parsed.scheme or url.startswith("//"):
            problems.append(f"{name}:{line}: loads {url} from the network; serve it from the site")
            continue
        target = urlparse(urljoin(page_url, url))
        local = site / target.path.lstrip("/")
        if not local.is_file():
            problems.append(f"{name}:{line}: loads {url}, which is not in the site ({local})")
        if target.path.endswith(f"/{MATHJAX}/MathJax.js"):
            mathjax.append((line, target))
    if page.math:
        pages_with_math += 1
        if not mathjax:
            problems.append(f"{name}: {page.math} equations but no {MATHJAX}/MathJax.js script")
        for line, target in mathjax:
            configs = re.findall(r"(?:^|&)config=([^&]+)", target.query)
            if not configs:
                problems.append(f"{name}:{line}: MathJax.js is loaded without ?config=")
            for config in ",".join(configs).split(","):
                if not (site / MATHJAX / "config" / f"{config}.js").is_file():
                    problems.append(f"{name}:{line}: MathJax config {config} is not in {site / MATHJAX / 'config'}")
if pages and not pages_with_math:
    problems.append(f"{site}: no page has an equation (<span|div class=\"arithmatex\">): is "
                    "pymdownx.arithmatex in mkdocs.yml's markdown_extensions?")
if pages_with_math:
    for name in MATHJAX_LOADS:
        if not (site / MATHJAX / name).is_file():
            problems.append(f"{site / MATHJAX / name}: missing; MathJax loads it for these pages "
                            "(docs/hooks/mathjax.py copies it)")

# 4. The sources, as GitHub reads them.
fence = re.compile(r"^ {0,3}(```|~~~)")
for path in sorted((source / "docs").rglob("*.md")):
    lines = path.read_text(encoding="utf-8").splitlines()
    in_fence = False
    kept = []
    for line in lines:
        if fence.match(line):
            in_fence = not in_fence
            kept.append("")
            continue
        kept.append("" if in_fence else re.sub(r"`[^`]*`", "", line))
    text = "\n".join(kept)
    for match in re.finditer(r"\$\$(.+?)\$\$|\$([^$\n]+?)\$", text, re.S):
        math = match.group(1) if match.group(1) is not None else match.group(2)
        start = match.start() + (2 if match.group(1) is not None else 1)
        for escape in re.finditer(r"\\[!-/:-@\[-`{-~]", math):
            line = text.count("\n", 0, start + escape.start()) + 1
            problems.append(f"{path.relative_to(source)}:{line}: {escape.group()} in an equation: GitHub's Markdown "
                            "reads it as an escape before the math renderer sees it; write \\thinspace, "
                            "\\lbrace/\\rbrace, \\cr (rows), \\text{...} instead")

    # Emphasis: GitHub runs its Markdown over the equations first, so a _ that can open an emphasis
    # (after a bracket: \hat{A}_1) and a later one that can close it (B_{1}) in the same paragraph
    # turn the text between them italic, and the equation breaks. The rules are CommonMark's.
    for block in re.finditer(r"(?:[^\n]|\n(?![ \t]*\n))+", text):
        paragraph = block.group()
        if "$" not in paragraph:
            continue
        opener = None
        for underscore in re.finditer(r"_", paragraph):
            before = paragraph[underscore.start() - 1] if underscore.start() else " "
            after = paragraph[underscore.end()] if underscore.end() < len(paragraph) else " "
            left = not after.isspace() and (not punctuation(after) or before.isspace() or punctuation(before))
            right = not before.isspace() and (not punctuation(before) or after.isspace() or punctuation(after))
            if opener is None and left and (not right or punctuation(before)):
                opener = underscore.start()
            elif opener is not None and right and (not left or punctuation(after)):
                line = text.count("\n", 0, block.start() + opener) + 1
                context = paragraph[max(0, opener - 25):underscore.end() + 5].replace("\n", " ")
                problems.append(f"{path.relative_to(source)}:{line}: GitHub's Markdown would read the _ "
                                f"pair in ...{context}... as emphasis and break the equation: put a letter "
                                "or digit before the first _ (name the bracketed vector: q = ..., q_z)")
                opener = None

for problem in problems:
    print(problem)
if problems:
    print(f"check_site_math: {len(problems)} problems")
    sys.exit(1)
print(f"check_site_math: {len(pages)} pages, {pages_with_math} with equations, typeset from the site's own MathJax")
