#!/usr/bin/env python3
"""Checks the reports one stoa-grade run wrote: the HTML report, the JUnit XML
and results.json exist, are not empty and are well formed; with --mistake NAME,
every failed case carries a known-mistake hint and at least one names NAME.

usage: check_reports.py REPORT.html JUNIT.xml RESULTS.json [--mistake NAME]
"""
import html.parser
import json
import sys
import xml.dom.minidom

VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source", "track", "wbr"}


class BalanceChecker(html.parser.HTMLParser):
    """Fails on an end tag that does not close the element open last."""

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.stack = []
        self.external = []

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if name == "src" and value and not value.startswith("data:"):
                self.external.append(value)
        if tag == "link" or tag == "script":
            self.external.append(tag)
        if tag not in VOID:
            self.stack.append((tag, self.getpos()))

    def handle_endtag(self, tag):
        if not self.stack or self.stack[-1][0] != tag:
            raise SystemExit("HTML: </%s> at line %d closes %s" % (tag, self.getpos()[0],
                                                                   self.stack[-1] if self.stack else "nothing"))
        self.stack.pop()


def read(path):
    with open(path, "rb") as file:
        data = file.read()
    if not data:
        raise SystemExit("%s is empty" % path)
    return data.decode("utf-8")


def main(argv):
    mistake = None
    if len(argv) == 6 and argv[4] == "--mistake":
        mistake = argv[5]
    elif len(argv) != 4:
        raise SystemExit(__doc__)
    html_path, junit_path, json_path = argv[1:4]

    page = read(html_path)
    if not page.startswith("<!DOCTYPE html>"):
        raise SystemExit("HTML: no <!DOCTYPE html> at the start of " + html_path)
    checker = BalanceChecker()
    checker.feed(page)
    checker.close()
    if checker.stack:
        raise SystemExit("HTML: unclosed elements %s" % checker.stack)
    if checker.external:
        raise SystemExit("HTML: loads external resources %s" % checker.external)

    document = xml.dom.minidom.parseString(read(junit_path).encode("utf-8"))
    cases = document.getElementsByTagName("testcase")
    if not cases:
        raise SystemExit("JUnit: no testcase in " + junit_path)

    results = json.loads(read(json_path))
    tests = results["tests"]
    if len(tests) != len(cases):
        raise SystemExit("results.json has %d tests, the JUnit XML %d cases" % (len(tests), len(cases)))

    if mistake is not None:
        failed = [t for t in tests if t["status"] == "failed"]
        named = [t for t in failed if t.get("extra_data", {}).get("hint_mistake") == mistake]
        if not named:
            raise SystemExit("no failed case's hint names the mistake %s: %s" %
                             (mistake, [(t["name"], t.get("extra_data")) for t in failed]))
        if "<code>%s</code>" % mistake not in page:
            raise SystemExit("the HTML report does not name the mistake " + mistake)
        if "known mistake %s)" % mistake not in read(junit_path):
            raise SystemExit("the JUnit XML does not name the mistake " + mistake)
    print("reports ok: %d cases, %d bytes of HTML%s" %
          (len(cases), len(page), ", hint names " + mistake if mistake else ""))


if __name__ == "__main__":
    main(sys.argv)
