#!/usr/bin/env python3
"""make_class.py SOURCE DEST COUNT LAB...: a made-up class of COUNT submissions
(DEST/student001/labs/ ...) for the class report's scale run (class_scale.sh).

Every submission starts as a finished labs/ tree (make_submission.py: the stubs
with the solutions' code pasted in). Then, by a fixed seed, each student is one
of these, in about these shares:

  finished        35%   as is
  equivalent      15%   one of the labs' equivalent rewrites applied (still correct)
  one mistake     25%   one planted mistake of the gallery (solutions/NN/mistakes/*.mistake)
  two mistakes    10%   two, in different labs where there are
  one stub         8%   one lab's student files handed in as the stubs (not attempted)
  compile error    5%   a line of nonsense at the end of one lab's first C++ file
  all stubs        2%   the stubs of every lab

Prints the count of each kind and which mistakes were planted.
"""
import collections
import glob
import os
import random
import re
import shutil
import subprocess
import sys

KINDS = [("finished", 35), ("equivalent", 15), ("one mistake", 25), ("two mistakes", 10), ("one stub", 8),
         ("compile error", 5), ("all stubs", 2)]


def patch(path, labs_dir, lab):
    """Applies a .mistake or .equivalent file to the finished tree; False when its text does not match."""
    text = open(path).read()
    name = re.search(r"^file:\s*(\S+)", text, re.M).group(1)
    find = text.split("--- find\n", 1)[1].split("--- replace\n", 1)[0]
    replace = text.split("--- replace\n", 1)[1].split("--- end", 1)[0]
    target = os.path.join(labs_dir, lab, "student", name)
    code = open(target).read()
    if code.count(find) != 1:
        return False
    open(target, "w").write(code.replace(find, replace))
    return True


def stub_lab(source, labs_dir, lab):
    for stub in glob.glob(os.path.join(source, "labs", lab, "student", "*")):
        shutil.copy(stub, os.path.join(labs_dir, lab, "student", os.path.basename(stub)))


def main():
    source, dest, count, labs = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4:]
    here = os.path.dirname(os.path.abspath(__file__))
    template = os.path.join(dest, ".finished")
    shutil.rmtree(dest, ignore_errors=True)
    subprocess.run([sys.executable, os.path.join(here, "make_submission.py"), source, os.path.join(template, "labs")],
                   check=True, stdout=subprocess.DEVNULL)
    mistakes = {lab: sorted(glob.glob(os.path.join(source, "solutions", lab, "mistakes", "*.mistake"))) for lab in labs}
    equivalents = {lab: sorted(glob.glob(os.path.join(source, "solutions", lab, "equivalents", "*.equivalent")))
                   for lab in labs}
    random_source = random.Random(28)
    kinds = collections.Counter()
    planted = collections.Counter()
    for number in range(1, count + 1):
        student = os.path.join(dest, f"student{number:03d}")
        shutil.copytree(template, student)
        labs_dir = os.path.join(student, "labs")
        kind = random_source.choices([k for k, _ in KINDS], weights=[w for _, w in KINDS])[0]
        if kind == "equivalent":
            lab = random_source.choice([lab for lab in labs if equivalents[lab]])
            if not patch(random_source.choice(equivalents[lab]), labs_dir, lab):
                kind = "finished"
        elif kind in ("one mistake", "two mistakes"):
            chosen = random_source.sample([lab for lab in labs if mistakes[lab]],
                                          k=min(2 if kind == "two mistakes" else 1, len(labs)))
            for lab in chosen:
                mistake = random_source.choice(mistakes[lab])
                if patch(mistake, labs_dir, lab):
                    planted[f"{lab}/{os.path.basename(mistake)[:-8]}"] += 1
        elif kind == "one stub":
            stub_lab(source, labs_dir, random_source.choice(labs))
        elif kind == "compile error":
            with_cpp = [lab for lab in labs if glob.glob(os.path.join(labs_dir, lab, "student", "*.cpp"))]
            lab = random_source.choice(with_cpp)
            first = sorted(glob.glob(os.path.join(labs_dir, lab, "student", "*.cpp")))[0]
            with open(first, "a") as code:
                code.write("this is not C++;\n")
        elif kind == "all stubs":
            for lab in labs:
                stub_lab(source, labs_dir, lab)
        kinds[kind] += 1
    shutil.rmtree(template)
    print(f"make_class.py: {count} submissions in {dest}: " + ", ".join(f"{n} {k}" for k, n in kinds.most_common()))
    print("planted: " + ", ".join(f"{name} x{n}" for name, n in planted.most_common()))


if __name__ == "__main__":
    main()
