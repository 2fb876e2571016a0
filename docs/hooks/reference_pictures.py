"""A mkdocs hook: the lab pages show the grader's reference pictures where they
live, autograder/references/, instead of a second copy under docs/.

A page links a picture by its place in the repository, which GitHub shows as
it is:  ![Reference picture of case sun](../../autograder/references/02_shading/sun.png)
(a case's reference) or .../02_shading/mistakes/no_half_vector/sun.png (a
planted mistake's gallery picture, written by stoa-grade --update-references).
For the site, each picture a page links is copied to references/... and the
link is rewritten to it.
"""
import posixpath
import re
from pathlib import Path

from mkdocs.structure.files import File

LINK = re.compile(r"\]\(((?:\.\./)+)autograder/references/([^)\s]+\.png)\)")


def _root(config):
    return Path(config["config_file_path"]).resolve().parent


def on_files(files, config):
    root = _root(config)
    docs = Path(config["docs_dir"]).resolve()
    linked = set()
    for page in sorted(docs.rglob("*.md")):
        for match in LINK.finditer(page.read_text(encoding="utf-8")):
            linked.add(match.group(2))
    for picture in sorted(linked):
        if (root / "autograder" / "references" / picture).is_file():
            files.append(File("references/" + picture, str(root / "autograder"), config["site_dir"],
                              config["use_directory_urls"]))
    return files


def on_page_markdown(markdown, page, config, files):
    # From the page's folder in docs/ to the site's references/ folder.
    up = posixpath.relpath("references", posixpath.dirname(Path(page.file.src_path).as_posix()))
    return LINK.sub(lambda match: "](" + up + "/" + match.group(2) + ")", markdown)
