#!/usr/bin/env python3
"""Every library the build looks for is in each list that installs it.

    check_dependency_lists.py ROOT

framework/cmake/StoaDependencies.cmake declares each library once, with
stoa_dependency(NAME ... PROVIDERS "Debian: PACKAGE; vcpkg: PORT; ..."). This
checks that each Debian package is in .ci/install-deps.sh's list and each vcpkg
port in vcpkg.json, and that vcpkg.json names no port the build does not use,
so that a library added to the build cannot be forgotten on one system.
"""
import json
import re
import sys
from pathlib import Path


def providers(cmake_text):
    """NAME -> {"Debian": [...], "vcpkg": [...]} from each stoa_dependency() call."""
    found = {}
    for call in re.finditer(r"^stoa_dependency\((\w+)(.*?)\)\s*$", cmake_text, re.M | re.S):
        name, body = call.group(1), call.group(2)
        text = re.search(r'PROVIDERS\s+"([^"]*)"', body)
        if not text:
            raise SystemExit(f"StoaDependencies.cmake: stoa_dependency({name} ...) has no PROVIDERS")
        entry = {}
        for part in text.group(1).split(";"):
            system, _, packages = part.partition(":")
            # "imgui[glut-binding,opengl3-binding]" is the port imgui; "(or ...)" is advice.
            words = re.sub(r"\(.*?\)|\[.*?\]", "", packages).replace(",", " ").split()
            entry[system.strip()] = words
        found[name] = entry
    return found


def main():
    root = Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    declared = providers((root / "framework/cmake/StoaDependencies.cmake").read_text())
    install = (root / ".ci/install-deps.sh").read_text()
    debian = set(re.search(r"packages=\((.*?)\)", install, re.S).group(1).split())
    manifest = json.loads((root / "vcpkg.json").read_text())
    ports = {d if isinstance(d, str) else d["name"] for d in manifest["dependencies"]}
    problems = []
    used_ports = {"catch2"}   # the tests' framework, found by find_package(Catch2)
    for name, entry in sorted(declared.items()):
        for system in ("Debian", "vcpkg"):
            if not entry.get(system):
                problems.append(f"stoa_dependency({name}): PROVIDERS names no {system} package")
        for package in entry.get("Debian", []):
            if package not in debian:
                problems.append(f"{name}: the Debian package {package} is not in .ci/install-deps.sh's list")
        for port in entry.get("vcpkg", []):
            used_ports.add(port)
            if port not in ports:
                problems.append(f"{name}: the vcpkg port {port} is not in vcpkg.json")
    for port in sorted(ports - used_ports):
        problems.append(f"vcpkg.json lists {port}, which no stoa_dependency() in StoaDependencies.cmake names")
    if len(declared) < 10:
        problems.append(f"only {len(declared)} stoa_dependency() calls found in StoaDependencies.cmake: the check reads it wrongly")
    for problem in problems:
        print("FAIL:", problem)
    if problems:
        return 1
    print(f"{len(declared)} libraries: each in .ci/install-deps.sh and vcpkg.json ({len(ports)} ports)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
