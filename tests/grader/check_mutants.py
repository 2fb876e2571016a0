#!/usr/bin/env python3
"""The mutation tool's mutants are what it says (autograder/mutation/mutants.py).

    check_mutants.py ROOT

For every lab: each mutant's find text occurs exactly once in its solution file
and differs from its replacement by one line; no mutant touches a line the stub
already has, a comment or a preprocessor line; IDs are unique and stable (the
same twice); every rule makes mutants somewhere; and equivalent-mutants.txt
names only mutants that exist.
"""
import sys
from pathlib import Path

root = Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
sys.path.insert(0, str(root / "autograder" / "mutation"))
import mutants as mutation  # noqa: E402
import mutate  # noqa: E402

problems = []
rules = set()
total = 0
labs = sorted(p.name for p in (root / "solutions").iterdir() if p.is_dir() and p.name[:2].isdigit())
all_ids = {}
for lab in labs:
    first = mutation.mutants_of_lab(root, lab)
    second = mutation.mutants_of_lab(root, lab)
    if [m.id for m in first] != [m.id for m in second]:
        problems.append(f"{lab}: the mutants' IDs differ between two runs")
    ids = [m.id for m in first]
    if len(set(ids)) != len(ids):
        problems.append(f"{lab}: two mutants share an ID")
    all_ids[lab] = set(ids)
    for mutant in first:
        rules.add(mutant.rule)
        source = (root / "solutions" / lab / "student" / mutant.file).read_text()
        stub = root / "labs" / lab / "student" / mutant.file
        given = {line.strip() for line in stub.read_text().splitlines()} if stub.exists() else set()
        if source.count(mutant.find) != 1:
            problems.append(f"{lab} {mutant.id}: its find text occurs {source.count(mutant.find)} times")
        old, new = mutant.find.splitlines(), mutant.replace.splitlines()
        changed = [i for i, (a, b) in enumerate(zip(old, new)) if a != b]
        if len(old) != len(new) or len(changed) != 1:
            problems.append(f"{lab} {mutant.id}: changes {len(changed)} lines, not one")
            continue
        line = old[changed[0]].strip()
        if line in given or line.startswith(("//", "#", "/*", "*")):
            problems.append(f"{lab} {mutant.id}: mutates a given, comment or preprocessor line: {line}")
    total += len(first)
for rule in ("relational", "arithmetic", "constant", "min-max", "swap-args", "drop-line", "normalize", "swizzle"):
    if rule not in rules:
        problems.append(f"no lab has a mutant of the rule {rule}")
for (lab, mutant_id) in mutate.read_equivalents(mutate.EQUIVALENTS):
    if mutant_id not in all_ids.get(lab, set()):
        problems.append(f"equivalent-mutants.txt lists {lab} {mutant_id}, which is not a mutant")
for problem in problems[:40]:
    print("FAIL:", problem)
if problems:
    sys.exit(1)
print(f"{total} mutants in {len(labs)} labs, {len(rules)} rules: each changes one student-written line, found once")
