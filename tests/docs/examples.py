"""Runs the shell examples of one Markdown file, as a reader would, so that
an example that no longer works is a failing test.

    examples.py FACET SOURCE_DIR SCRATCH_DIR FILE.md [LINE]
    examples.py --list FILE.md

With LINE, only the example that starts on that line runs (one ctest entry
per example, so that they run side by side); --list prints the line of
each example, one per line.

An example is a code block (indented by four spaces, or fenced as ```sh,
```bash or ```console) whose first line starts with a command: facet,
./build/app/facet, ./scripts/..., $, mkdir, cmake, ffmpeg, valgrind,
xvfb-run, python3. Other blocks (JSON, diagrams, tables of output) are
text. An example runs in SCRATCH_DIR, which holds copies of assets/ and docs/ (so that the examples'
relative paths work and nothing is written into the source tree); `facet`
and ./build/app/facet are the facet built. Each command must exit 0. In a
block whose lines start with `$ `, those lines are the commands and the
lines after one are what it prints on stdout, which must match.

A block that cannot run here says so on the line before it (blank lines
between allowed), with a reason the reader sees too:

    <!-- not run: REASON -->

Such a block is reported as skipped (exit code 77), with its reason.
"""
import os
import re
import shutil
import stat
import subprocess
import sys
import time

if sys.argv[1] == "--list":
    doc = sys.argv[2]
else:
    facet, source, scratch, doc = sys.argv[1:5]
    only = int(sys.argv[5]) if len(sys.argv) > 5 else None
    facet = os.path.abspath(facet)
    name = os.path.relpath(doc, source)
lines = open(doc, encoding="utf-8").read().split("\n")

COMMAND = re.compile(r"^(facet\b|\./build/app/facet\b|\./scripts/|\$ |mkdir\b|cmake\b|ctest\b|ffmpeg\b|valgrind\b|xvfb-run\b|python3\b)")
NOT_RUN = re.compile(r"^<!-- not run: (.*\S) -->$")


def blocks():
    """(first line number, lines of the block, reason it is not run or None)."""
    i = 0
    while i < len(lines):
        line = lines[i]
        fence = re.match(r"^```\s*(\w*)", line)
        if fence:
            j = i + 1
            while j < len(lines) and not lines[j].startswith("```"):
                j += 1
            if fence.group(1) in ("sh", "bash", "console", "shell"):
                yield i + 2, lines[i + 1:j], i
            i = j + 1
            continue
        # An indented block: four spaces after a blank line, an HTML comment
        # or the start of the file, outside a list item's paragraph.
        previous = lines[i - 1] if i > 0 else ""
        if line.startswith("    ") and line.strip() and (not previous.strip() or previous.startswith("<!--")):
            j = i
            while j < len(lines) and (lines[j].startswith("    ") or not lines[j].strip()):
                j += 1
            while j > i and not lines[j - 1].strip():
                j -= 1
            yield i + 1, [l[4:] for l in lines[i:j]], i
            i = j
            continue
        i += 1


def reason_before(start):
    k = start - 1
    while k >= 0 and not lines[k].strip():
        k -= 1
    if k >= 0:
        m = NOT_RUN.match(lines[k].strip())
        if m:
            return m.group(1)
    return None


def examples():
    """(first line number, lines, first line of the block's markup) of each example."""
    for first, block, start in blocks():
        if block and COMMAND.match(block[0]):
            yield first, block, start


if sys.argv[1] == "--list":
    for first, _, _ in examples():
        print(first)
    sys.exit(0)

# The scratch folder: copies of what the examples read, and facet where they call it.
shutil.rmtree(scratch, ignore_errors=True)
os.makedirs(os.path.join(scratch, "build", "app"))
for folder in ("assets", "docs"):
    shutil.copytree(os.path.join(source, folder), os.path.join(scratch, folder))
bin_dir = os.path.join(scratch, "bin")
os.makedirs(bin_dir)
for link in (os.path.join(bin_dir, "facet"), os.path.join(scratch, "build", "app", "facet")):
    os.symlink(facet, link)
env = dict(os.environ, PATH=bin_dir + os.pathsep + os.environ.get("PATH", ""))

run = skipped = 0
failures = []
for first, block, start in examples():
    if only is not None and first != only:
        continue
    text = list(block)
    reason = reason_before(start)
    if reason is not None:
        print(f"not run: {name}:{first}: {text[0]}\n  because {reason}")
        skipped += 1
        continue
    # Join continued lines; then pair each command with the output it shows.
    joined = []
    for l in text:
        if joined and joined[-1].endswith("\\"):
            joined[-1] = joined[-1][:-1] + " " + l.strip()
        else:
            joined.append(l)
    prompted = any(l.startswith("$ ") for l in joined)
    steps = []  # (line number, command, expected stdout lines or None)
    for offset, l in enumerate(joined):
        if not l.strip():
            continue
        if prompted:
            if l.startswith("$ "):
                steps.append([first + offset, l[2:], []])
            else:
                steps[-1][2].append(l.rstrip())
        else:
            steps.append([first + offset, l, None])
    for number, command, expected in steps:
        print(f"$ {command}    ({name}:{number})", flush=True)
        began = time.monotonic()
        result = subprocess.run(["bash", "-o", "pipefail", "-c", command], cwd=scratch, env=env, capture_output=True, text=True)
        print(f"  ({time.monotonic() - began:.1f} s)")
        run += 1
        shown = (result.stdout + result.stderr).strip().splitlines()
        for out in shown[-5:]:
            print("  " + out)
        if result.returncode != 0:
            failures.append(f"{name}:{number}: exit code {result.returncode}: {command}")
        elif expected:
            printed = [l.rstrip() for l in result.stdout.strip("\n").split("\n")]
            if printed != expected:
                failures.append(f"{name}:{number}: printed {printed}, the example shows {expected}: {command}")

print(f"{name}: {run} commands run, {skipped} blocks not run (reasons above), {len(failures)} failed")
for failure in failures:
    print("FAILED " + failure)
if run == 0 and skipped == 0:
    print(f"{name}: no example found" + (f" on line {only}" if only is not None else ""))
    sys.exit(1)
sys.exit(1 if failures else 77 if run == 0 else 0)
