"""MkDocs hook (mkdocs.yml, `hooks:`): colours for the code blocks, made at build time.

The mkdocs theme's highlight.js comes from a CDN, so mkdocs.yml turns it off
(`highlightjs: false`) and lets python-markdown's codehilite colour the code with Pygments
while it builds. This hook writes the matching style sheet, site/css/pygments.css, which
mkdocs.yml's extra_css names: the pages load nothing from the network.
"""

import importlib.util
from pathlib import Path

from mkdocs.exceptions import PluginError

STYLE = "default"
SHEET = "css/pygments.css"


def on_config(config, **kwargs):
    # codehilite needs it too, and says nothing when it is missing.
    if importlib.util.find_spec("pygments") is None:
        raise PluginError("Pygments not found: the docs colour their code with it. Install Debian's "
                          "python3-pygments (sudo apt-get install python3-pygments, or .ci/install-deps.sh).")
    return config


def on_post_build(config, **kwargs):
    from pygments.formatters import HtmlFormatter

    sheet = Path(config["site_dir"]) / SHEET
    sheet.parent.mkdir(parents=True, exist_ok=True)
    sheet.write_text(HtmlFormatter(style=STYLE).get_style_defs(".codehilite") + "\n", encoding="utf-8")
