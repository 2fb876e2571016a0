#!/usr/bin/env python3
"""How many realistic bugs the grader catches: a mutation score per lab.

    autograder/mutation/mutate.py [--lab NN ...] [--sample N] [--seed S] [--mutant ID ...] [--jobs N]
                                  [--build-dir DIR] [--out DIR] [--list] [--min-score PERCENT]

For each lab (all by default), makes mutants of the solutions' student files
(mutants.py: operators, constants, min/max, swapped arguments, removed lines,
dropped normalize, permuted swizzles; only on lines the student writes), builds
each as a lab program the way a planted mistake is built (only the mutated file
compiles; STOA_MUTANTS_DIR in framework/cmake/StoaLab.cmake), and grades it
with the lab's cases and property checks (stoa-grade --bin-dir). A mutant is
  killed        some case or check fails
  survived      every case and check passes: a bug the grader does not see
  not compiled  the change does not build (not counted in the score)
  equivalent    listed in equivalent-mutants.txt with why it cannot change the
                result (not built, not counted)
The score is killed / (killed + survived). A hint that fires on a mutant must
be a gallery mistake of the same file and function, or one whose hint lists the
mutant's file among the known causes: one naming another cause is reported
(hints are right or silent).

Writes DIR/mutation-report.md (per lab, then every survivor as a diff) and
DIR/mutation-report.json; prints progress on stderr and the summary on stdout.
Exit status 0, or 1 when --min-score is given and a lab scores below it, 2 on
bad usage. The full sweep of every mutant of every lab is an instructor's
command (docs/instructor-guide.md, "Mutation score"); --sample N takes N
mutants a lab, chosen by --seed, for a quick look.
"""
import argparse
import json
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import mutants as mutation  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
EQUIVALENTS = Path(__file__).resolve().parent / "equivalent-mutants.txt"


def say(text):
    print(text, file=sys.stderr, flush=True)


def read_equivalents(path):
    """{(lab, id): reason} from lines "NN_name MUTANT_ID -- why it cannot change the result"."""
    listed = {}
    if not path.exists():
        return listed
    for number, line in enumerate(path.read_text().splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        match = re.match(r"^(\d\d_\w+)\s+(\w+)\s+--\s+(\S.*)$", line)
        if not match:
            raise SystemExit(f"{path}:{number}: expected 'NN_name MUTANT_ID -- reason', found: {line}")
        listed[(match.group(1), match.group(2))] = match.group(3)
    return listed


def labs_named(names):
    if not (ROOT / "solutions").is_dir():
        raise SystemExit(f"mutate.py: {ROOT} has no solutions/ folder: mutants are made from the solutions, "
                         "which the course's full repository has and a student release does not")
    every = sorted(p.name for p in (ROOT / "solutions").iterdir() if p.is_dir() and re.match(r"\d\d_", p.name))
    if not names:
        return every
    chosen = []
    for name in names:
        found = [lab for lab in every if lab == name or lab.startswith(name + "_")]
        if not found:
            raise SystemExit(f"mutate.py: --lab {name}: no such lab (labs: {', '.join(every)})")
        chosen += found
    return chosen


def gallery_causes(lab):
    """{mistake name: (file, function, hint)} for the lab's planted mistakes."""
    causes = {}
    for path in sorted((ROOT / "solutions" / lab / "mistakes").glob("*.mistake")):
        text = path.read_text()
        file = re.search(r"^file:\s*(\S+)", text, re.M).group(1)
        find = text.split("--- find\n", 1)[1].split("--- replace\n", 1)[0]
        source = (ROOT / "solutions" / lab / "student" / file).read_text()
        line = source[:source.find(find)].count("\n") if find in source else 0
        functions = mutation.enclosing_functions(source.splitlines())
        hint = re.search(r"^hint:\s*(.*)$", text, re.M).group(1)
        causes[path.stem] = (file, functions[line] if line < len(functions) else "", hint)
    return causes


def names_cause(cause, mutant):
    """Whether a gallery mistake's hint names the mutant's cause: the mistake is in the
    same function of the same file, or its hint names the mutant's file among the known
    causes (as stoa-grade --check-hints accepts for mistakes outside the gallery)."""
    if cause is None:
        return False
    file, function, hint = cause
    return (file, function) == (mutant.file, mutant.function) or Path(mutant.file).name in hint


def fingerprint(lab):
    """What a lab's programs are built from and graded with: its folders' files,
    their sizes and modification times. A change after the mutants were built
    would grade old programs against new cases (a check they do not know fails
    as an error and would count as a kill)."""
    files = []
    for folder in (ROOT / "labs" / lab, ROOT / "solutions" / lab, ROOT / "shaders"):
        for path in sorted(folder.rglob("*")):
            if path.is_file():
                status = path.stat()
                files.append((str(path.relative_to(ROOT)), status.st_size, status.st_mtime_ns))
    return files


def configure_and_build(build, mutants_dir, chosen, jobs):
    command = ["cmake", "-S", str(ROOT), "-B", str(build), "-DSTOA_USE_SOLUTIONS=ON", "-DSTOA_BUILD_TESTS=OFF",
               f"-DSTOA_MUTANTS_DIR={mutants_dir}", "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG"]
    if shutil.which("ninja") and not (build / "CMakeCache.txt").exists():
        command += ["-G", "Ninja"]
    if shutil.which("ccache"):
        command += ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"]
    say(f"mutate: configuring {build}")
    configured = subprocess.run(command, capture_output=True, text=True)
    if configured.returncode != 0:
        raise SystemExit("mutate: the configure step failed:\n" + configured.stdout[-3000:] + configured.stderr[-3000:])
    targets = ["stoa-grade"] + [f"{m.lab}-mutant-{m.id}" for m in chosen]
    say(f"mutate: building stoa-grade and {len(chosen)} mutant programs (-k 0: a mutant that does not compile is counted so)")
    log = build / "mutants-build.log"
    with open(log, "w") as out:
        subprocess.run(["cmake", "--build", str(build), "-j", str(jobs), "--target", *targets, "--", "-k", "0"],
                       stdout=out, stderr=subprocess.STDOUT)
    if not (build / "bin" / "stoa-grade").exists():
        raise SystemExit(f"mutate: stoa-grade did not build; see {log}")


def grade(build, mutant, jobs, work):
    """The mutant's verdict: (status, failed tests, hints fired)."""
    folder = build / "bin" / "mutants" / f"{mutant.lab}.{mutant.id}"
    if not folder.is_dir() or not any(folder.iterdir()):
        return "not compiled", [], []
    results = work / f"{mutant.lab}.{mutant.id}.json"
    subprocess.run([str(build / "bin" / "stoa-grade"), "--bin-dir", str(folder), "--lab", mutant.lab,
                    "--json", str(results), "--jobs", str(jobs), "--work-dir", str(work / "images")],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    if not results.exists():
        return "killed", ["(the grader wrote no results)"], []
    tests = json.loads(results.read_text()).get("tests", [])
    failed = [t["name"].split("/", 1)[-1] for t in tests if t.get("status") != "passed"]
    hints = sorted({t.get("extra_data", {}).get("hint_mistake") for t in tests} - {None})
    return ("killed" if failed else "survived"), failed, hints


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lab", action="append", default=[], help="NN or NN_name (repeatable); default: every lab")
    parser.add_argument("--sample", type=int, default=0, help="grade N mutants a lab (0: all)")
    parser.add_argument("--mutant", action="append", default=[], metavar="ID",
                        help="only this mutant (repeatable; IDs as the report and --list give them)")
    parser.add_argument("--seed", type=int, default=1, help="which sample (default 1)")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    parser.add_argument("--build-dir", type=Path, default=ROOT / "build-mutants")
    parser.add_argument("--out", type=Path, default=None, help="where the report goes (default: the build folder)")
    parser.add_argument("--list", action="store_true", help="only list the mutants, as diffs, and stop")
    parser.add_argument("--min-score", type=float, default=None, help="exit 1 when a lab scores below PERCENT")
    args = parser.parse_args()
    if args.sample < 0 or args.jobs < 1:
        parser.error("--sample must be 0 or more and --jobs 1 or more")
    started = time.time()
    labs = labs_named(args.lab)
    equivalents = read_equivalents(EQUIVALENTS)

    per_lab, chosen = {}, []
    for lab in labs:
        every = mutation.mutants_of_lab(ROOT, lab)
        ids = {m.id for m in every}
        stale = [key[1] for key in equivalents if key[0] == lab and key[1] not in ids]
        for mutant_id in stale:
            say(f"mutate: {EQUIVALENTS.name} lists {lab} {mutant_id}, which is no longer a mutant (the solution changed)")
        live = sorted((m for m in every if (lab, m.id) not in equivalents), key=lambda m: m.id)
        equivalent = len(every) - len(live)
        if args.mutant:
            live = [m for m in live if m.id in args.mutant]
        picked = random.Random(f"{args.seed}:{lab}").sample(live, min(args.sample, len(live))) if args.sample else live
        per_lab[lab] = {"generated": len(every), "equivalent": equivalent, "graded": len(picked)}
        chosen += picked
    unknown = set(args.mutant) - {m.id for m in chosen}
    if unknown:
        parser.error(f"--mutant {', '.join(sorted(unknown))}: no such mutant in {', '.join(labs)} "
                     "(or listed as equivalent)")
    if args.list:
        for mutant in chosen:
            print(mutant.id)
            print(mutant.diff())
        return 0

    build = args.build_dir.resolve()
    out = (args.out or build).resolve()
    mutants_dir = build / "mutants"
    shutil.rmtree(mutants_dir, ignore_errors=True)
    for mutant in chosen:
        folder = mutants_dir / mutant.lab / "mistakes"
        folder.mkdir(parents=True, exist_ok=True)
        (folder / f"{mutant.id}.mistake").write_text(mutant.mistake_text())
    sources = {lab: fingerprint(lab) for lab in labs}
    configure_and_build(build, mutants_dir, chosen, args.jobs)
    built = time.time()

    causes = {lab: gallery_causes(lab) for lab in labs}
    verdicts = []
    stale = None
    with tempfile.TemporaryDirectory(prefix="stoa-mutants-") as temporary:
        work = Path(temporary)
        for number, mutant in enumerate(chosen, 1):
            if fingerprint(mutant.lab) != sources[mutant.lab]:
                stale = mutant.lab
                say(f"mutate: stopped before mutant {number} of {len(chosen)}: labs/{stale}, solutions/{stale} or "
                    "shaders/ changed after the mutants were built, and their programs would be graded against "
                    "the new cases; the report holds what was graded before, run the sweep again for the rest")
                break
            status, failed, hints = grade(build, mutant, args.jobs, work)
            wrong_hints = [h for h in hints if not names_cause(causes[mutant.lab].get(h), mutant)]
            verdicts.append({"lab": mutant.lab, "id": mutant.id, "rule": mutant.rule, "file": mutant.file,
                             "line": mutant.line, "function": mutant.function, "status": status, "failed": failed,
                             "hints": hints, "wrong_hints": wrong_hints, "diff": mutant.diff()})
            detail = f"killed by {', '.join(failed[:3])}" if status == "killed" else status
            say(f"[{number}/{len(chosen)}] {mutant.lab} {mutant.id}: {detail}"
                + (f"; hint {', '.join(wrong_hints)} names another cause" if wrong_hints else ""))
    graded = time.time()

    for lab in labs:
        mine = [v for v in verdicts if v["lab"] == lab]
        per_lab[lab]["graded"] = len(mine)
        counts = {s: sum(v["status"] == s for v in mine) for s in ("killed", "survived", "not compiled")}
        counted = counts["killed"] + counts["survived"]
        per_lab[lab].update(counts)
        per_lab[lab]["score"] = round(100.0 * counts["killed"] / counted, 1) if counted else None
        per_lab[lab]["wrong_hints"] = sum(bool(v["wrong_hints"]) for v in mine)
    report = {"labs": per_lab, "mutants": verdicts, "sample": args.sample, "seed": args.seed,
              "seconds": {"build": round(built - started, 1), "grade": round(graded - built, 1)}}
    out.mkdir(parents=True, exist_ok=True)
    (out / "mutation-report.json").write_text(json.dumps(report, indent=1) + "\n")
    (out / "mutation-report.md").write_text(markdown(report))
    print(summary_table(per_lab))
    print(f"{len(chosen)} mutants built in {built - started:.0f} s and graded in {graded - built:.0f} s; "
          f"report: {out / 'mutation-report.md'}")
    if stale:
        return 2
    if args.min_score is not None:
        low = [lab for lab, row in per_lab.items() if row["score"] is not None and row["score"] < args.min_score]
        if low:
            print(f"below {args.min_score}%: {', '.join(low)}")
            return 1
    return 0


def summary_table(per_lab):
    rows = ["| lab | mutants | equivalent | graded | not compiled | killed | survived | score | wrong hints |",
            "|---|---|---|---|---|---|---|---|---|"]
    for lab, row in per_lab.items():
        score = "-" if row.get("score") is None else f"{row['score']:.1f}%"
        rows.append(f"| {lab} | {row['generated']} | {row['equivalent']} | {row['graded']} | {row.get('not compiled', 0)} "
                    f"| {row.get('killed', 0)} | {row.get('survived', 0)} | {score} | {row.get('wrong_hints', 0)} |")
    return "\n".join(rows)


def markdown(report):
    lines = ["# Mutation report", "",
             f"Sample: {report['sample'] or 'every mutant'} a lab (seed {report['seed']}); built in "
             f"{report['seconds']['build']} s, graded in {report['seconds']['grade']} s.", "",
             summary_table(report["labs"]), "", "## Survivors", "",
             "Each passes every case and check. Kill it with a case or check (and a planted mistake that only it "
             "catches), or list it in autograder/mutation/equivalent-mutants.txt with why it cannot change the result.",
             ""]
    for verdict in report["mutants"]:
        if verdict["status"] == "survived":
            lines += [f"### {verdict['lab']} {verdict['id']}", "", "```diff", verdict["diff"].rstrip(), "```", ""]
    wrong = [v for v in report["mutants"] if v["wrong_hints"]]
    if wrong:
        lines += ["## Hints that name another cause", ""]
        for verdict in wrong:
            lines += [f"- {verdict['lab']} {verdict['id']} ({verdict['file']}, {verdict['function'] or '?'}): "
                      f"hint {', '.join(verdict['wrong_hints'])}"]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    sys.exit(main())
