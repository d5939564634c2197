#!/usr/bin/env python3
"""The mutations of scripts/mutations.txt: their parser, and the steps of
scripts/mutate.sh that need it. A mutation whose `from` text no longer
occurs in its file breaks nothing and would be reported as not applying
only when mutate.sh runs (hours); --check says so in a second, as the
ctest entry mutations.every_mutation_applies.

  mutations.py --check [--build DIR [--ctest CTEST]]   every `from` occurs in its file, every
                                       `expect` compiles, and (with a build) names a ctest entry
  mutations.py --list [REGEX]          the names of the mutations (matching REGEX)
  mutations.py --apply NAME --root DIR --backup DIR    edits the copy in DIR, keeping its files
  mutations.py --restore --root DIR --backup DIR       puts the kept files back
  mutations.py --select NAME --build DIR   ctest -I's list of the entries a run of the mutation
                                           needs: the quick tier and every one its expect names
  mutations.py --named NAME            the lines of stdin (ctest names) its expect names
"""
import argparse
import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


class Mutation:
    def __init__(self, name):
        self.name = name
        self.edits = []  # [file, from, to]
        self.expect = ""


def parse(path=ROOT / "scripts" / "mutations.txt"):
    """The mutations in file order; exits 64 on a line it cannot read."""
    mutations = []
    for number, line in enumerate(path.read_text().splitlines(), 1):
        if not line or line.startswith("#"):
            continue
        key, _, value = line.partition(": ")
        current = mutations[-1] if mutations else None
        if key == "name":
            mutations.append(Mutation(value))
        elif current and key == "file":
            current.edits.append([value, None, None])
        elif current and current.edits and key in ("from", "to"):
            current.edits[-1][1 if key == "from" else 2] = value
        elif current and key == "expect":
            current.expect = value
        else:
            sys.exit(f"mutations.txt:{number}: cannot read: {line}")
    return mutations


def find(name):
    for mutation in parse():
        if mutation.name == name:
            return mutation
    sys.exit(f"mutations.txt: no mutation named '{name}'")


def ctest_names(build, ctest="ctest"):
    """The ctest entries of a build, in ctest's order (entry k is number k + 1), and their labels."""
    listing = subprocess.run([ctest, "--test-dir", str(build), "-N", "--show-only=json-v1"], check=True, capture_output=True, text=True)
    tests = json.loads(listing.stdout)["tests"]
    labels = [next((p["value"] for p in t.get("properties", []) if p["name"] == "LABELS"), []) for t in tests]
    return [t["name"] for t in tests], labels


def check(build, ctest):
    problems = []
    names = ctest_names(build, ctest)[0] if build else None
    mutations = parse()
    for m in mutations:
        if not m.edits or not m.expect:
            problems.append(f"'{m.name}': needs at least one file/from/to and an expect")
        for file, old, new in m.edits:
            if old is None or new is None:
                problems.append(f"'{m.name}': {file}: needs a from and a to")
            elif not (ROOT / file).is_file():
                problems.append(f"'{m.name}': {file}: no such file")
            elif old not in (ROOT / file).read_text():
                problems.append(f"'{m.name}': '{old}' not found in {file}")
        try:
            expect = re.compile(m.expect)
        except re.error as e:
            problems.append(f"'{m.name}': expect '{m.expect}': {e}")
            continue
        if names is not None and not any(expect.search(n) for n in names):
            problems.append(f"'{m.name}': expect '{m.expect}' names no ctest entry")
    for problem in problems:
        print(problem)
    print(f"{len(mutations)} mutations, {len(problems)} problems")
    return 1 if problems else 0


def apply(name, root, backup):
    """Each edit keeps its file as it was before it, so that restore, last edit first, undoes them all."""
    backup.mkdir(parents=True, exist_ok=True)
    for k, (file, old, new) in enumerate(find(name).edits):
        target = root / file
        shutil.copyfile(target, backup / f"original.{k}")
        (backup / f"original.{k}.path").write_text(file)
        text = target.read_text()
        if old not in text:
            sys.exit(f"mutation '{name}': '{old}' not found in {file}")
        target.write_text(text.replace(old, new))


def restore(root, backup):
    """Puts the files back with a new modification time (not the kept one), so that make builds them again."""
    kept = sorted(backup.glob("original.*.path"), key=lambda p: int(p.name.split(".")[1]), reverse=True)
    for path in kept:
        original = path.with_suffix("")
        shutil.copyfile(original, root / path.read_text())
        original.unlink()
        path.unlink()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    action = parser.add_mutually_exclusive_group(required=True)
    action.add_argument("--check", action="store_true")
    action.add_argument("--list", nargs="?", const="", metavar="REGEX")
    action.add_argument("--apply", metavar="NAME")
    action.add_argument("--restore", action="store_true")
    action.add_argument("--select", metavar="NAME")
    action.add_argument("--named", metavar="NAME")
    parser.add_argument("--build", type=Path)
    parser.add_argument("--ctest", default="ctest", help="the ctest that lists the build's entries")
    parser.add_argument("--root", type=Path)
    parser.add_argument("--backup", type=Path)
    args = parser.parse_args()
    if args.check:
        return check(args.build, args.ctest)
    if args.list is not None:
        for m in parse():
            if re.search(args.list, m.name):
                print(m.name)
    elif args.apply:
        apply(args.apply, args.root, args.backup)
    elif args.restore:
        restore(args.root, args.backup)
    elif args.select:
        expect = re.compile(find(args.select).expect)
        names, labels = ctest_names(args.build)
        chosen = [str(k + 1) for k, (n, l) in enumerate(zip(names, labels)) if "quick" in l or expect.search(n)]
        print(",0,," + ",".join(chosen))
    else:
        expect = re.compile(find(args.named).expect)
        for line in sys.stdin:
            if expect.search(line.rstrip("\n")):
                print(line, end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())
