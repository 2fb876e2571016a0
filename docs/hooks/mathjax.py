"""MkDocs hook (mkdocs.yml, `hooks:`): typesets the pages' equations with MathJax, served from
the site itself.

The pages write equations as $...$ (inline) and $$...$$ (display, on lines of their own), which
GitHub renders as they stand. In the site, pymdownx.arithmatex (generic mode) turns them into
<span class="arithmatex">\\(...\\)</span> and <div class="arithmatex">\\[...\\]</div>, and this hook

- adds MathJax to every page that has such an element (a page without equations loads nothing);
- copies the part of MathJax 2 that one configuration needs (TeX input, CommonHTML output,
  config TeX-AMS_CHTML: MathJax.js, that config, the jaxes, the operator tables, the TeX
  extensions the input loads on demand, the woff fonts) from Debian's libjs-mathjax into
  site/mathjax/, about 1.3 MB in 94 files;
- leaves itself out of the site.

Nothing is fetched from the network, and no MathJax file is kept in this repository: install
libjs-mathjax (.ci/install-deps.sh does), or point STOA_MATHJAX_DIR at an unpacked MathJax 2.7.
tests/docs/check_site_math.py checks the built site.
"""

import os
import shutil
from pathlib import Path

from mkdocs.exceptions import PluginError
from mkdocs.utils import get_relative_url

MATHJAX_DIR = Path(os.environ.get("STOA_MATHJAX_DIR", "/usr/share/javascript/mathjax"))
SITE_FOLDER = "mathjax"  # site/mathjax/
CONFIG = "TeX-AMS_CHTML"

# What the browser may request with this configuration, relative to the MathJax folder.
FILES = [
    "MathJax.js",
    f"config/{CONFIG}.js",
    "jax/input/TeX/*.js",
    "jax/output/CommonHTML/*.js",
    "jax/output/CommonHTML/autoload/*.js",   # tables (matrices, aligned), enclosures, ...
    "jax/output/CommonHTML/fonts/TeX/*.js",  # glyph data beyond the main fonts
    "jax/element/mml/*.js",
    "jax/element/mml/optable/*.js",          # the operator dictionary, loaded block by block
    "extensions/TeX/*.js",                   # macros the TeX input loads on demand (\boldsymbol, ...)
    "extensions/MathMenu.js",
    "extensions/MathZoom.js",
    "fonts/HTML-CSS/TeX/woff/*.woff",
]
# The files that must be there for any equation to show: a clear error when one is missing.
ESSENTIAL = [
    "MathJax.js",
    f"config/{CONFIG}.js",
    "jax/output/CommonHTML/jax.js",
    "fonts/HTML-CSS/TeX/woff/MathJax_Main-Regular.woff",
]

# What each page with equations gets: the delimiters arithmatex writes in generic mode, only its
# elements, and a display equation wider than a narrow window scrolls instead of running off.
PAGE_CONFIG = """<style>div.arithmatex { overflow-x: auto; overflow-y: hidden; }</style>
<script type="text/x-mathjax-config">
MathJax.Hub.Config({
  tex2jax: {inlineMath: [["\\\\(", "\\\\)"]], displayMath: [["\\\\[", "\\\\]"]],
            processEscapes: false, processEnvironments: false,
            ignoreClass: ".*|", processClass: "arithmatex"},
  CommonHTML: {linebreaks: {automatic: false}},
  messageStyle: "none"
});
</script>
"""


def _missing_mathjax():
    return [name for name in ESSENTIAL if not (MATHJAX_DIR / name).is_file()]


def on_config(config, **kwargs):
    missing = _missing_mathjax()
    if missing:
        raise PluginError(
            f"MathJax 2 not found in {MATHJAX_DIR} (missing {', '.join(missing)}): the docs typeset "
            "their equations with it. Install Debian's libjs-mathjax (sudo apt-get install libjs-mathjax, "
            "or .ci/install-deps.sh), or set STOA_MATHJAX_DIR to an unpacked MathJax 2.7.")
    return config


def on_files(files, **kwargs):
    # The hooks live under docs/ (the top level is fixed); they are no pages of the site.
    for file in list(files):
        if file.src_path.replace(os.sep, "/").startswith("hooks/"):
            files.remove(file)
    return files


def on_post_page(output, page, config, **kwargs):
    if 'class="arithmatex"' not in output:
        return output
    src = get_relative_url(f"{SITE_FOLDER}/MathJax.js", page.url) + f"?config={CONFIG}"
    scripts = PAGE_CONFIG + f'<script src="{src}"></script>\n'
    head_end = output.find("</head>")
    if head_end < 0:
        raise PluginError(f"{page.file.src_path}: no </head> to add MathJax to")
    return output[:head_end] + scripts + output[head_end:]


def on_post_build(config, **kwargs):
    target = Path(config["site_dir"]) / SITE_FOLDER
    if target.exists():
        shutil.rmtree(target)
    for pattern in FILES:
        sources = sorted(MATHJAX_DIR.glob(pattern))
        if not sources:
            raise PluginError(f"MathJax in {MATHJAX_DIR} has no {pattern}: is it MathJax 2.7?")
        for source in sources:
            destination = target / source.relative_to(MATHJAX_DIR)
            destination.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(source, destination)  # follows links: a site must not point out of itself
