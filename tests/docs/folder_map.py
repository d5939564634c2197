"""The README's folder map against the tree: every folder of the repository
(the top level, every folder under renderer/, app/ and assets/) has its
line in the map, and every folder the map names exists. Folders inside
tests/ are covered by tests/ as a whole.

    folder_map.py SOURCE_DIR
"""
import os
import re
import subprocess
import sys

source = sys.argv[1]
readme = open(os.path.join(source, "README.md"), encoding="utf-8").read()
begin = re.search(r"^<!-- folder map\b.*-->$", readme, re.M)
end = re.search(r"^<!-- end of folder map -->$", readme, re.M)
assert begin and end and begin.end() < end.start(), "README.md has no folder map between its two markers"

mapped = []
for line in readme[begin.end():end.start()].splitlines():
    row = re.match(r"^\| `([^`]+)` \|", line)
    if row:
        mapped.append(row.group(1).rstrip("/"))
    elif line.strip() and not re.match(r"^\| (folder|---)", line):
        sys.exit(f"README.md: a line of the folder map that is not a row `folder` | ...: {line}")

# The repository's folders: those of git's files when the source is a
# checkout's top (not a copy inside one, as scripts/mutate.sh makes); else
# those of the files on disk, build folders and caches left out.
def git_files():
    try:
        top = subprocess.run(["git", "-C", source, "rev-parse", "--show-toplevel"], check=True, capture_output=True, text=True).stdout.strip()
        if os.path.realpath(top) != os.path.realpath(source):
            return None
        return subprocess.run(["git", "-C", source, "ls-files"], check=True, capture_output=True, text=True).stdout.splitlines()
    except (OSError, subprocess.CalledProcessError):
        return None

files = git_files()
if files is None:
    files = []
    for root, dirs, names in os.walk(source):
        dirs[:] = [d for d in dirs if d not in (".git", "__pycache__") and not d.startswith("build")]
        rel = os.path.relpath(root, source).replace(os.sep, "/")
        files += [name if rel == "." else f"{rel}/{name}" for name in names]
folders = {os.path.dirname(f) for f in files}
folders = {"/".join(f.split("/")[:i]) for f in folders if f for i in range(1, f.count("/") + 2)}

def must_be_mapped(folder):
    parts = folder.split("/")
    return len(parts) == 1 or parts[0] == "renderer" or (parts[0] in ("app", "assets") and len(parts) == 2)

problems = []
for folder in sorted(f for f in folders if must_be_mapped(f)):
    if folder not in mapped:
        problems.append(f"{folder}/ is a folder of the repository the README's folder map leaves out")
for folder in mapped:
    if folder not in folders:
        problems.append(f"{folder}/ is in the README's folder map but not a folder of the repository")
    if mapped.count(folder) > 1:
        problems.append(f"{folder}/ has more than one line in the README's folder map")
for problem in dict.fromkeys(problems):
    print(problem)
if problems:
    sys.exit(1)
print(f"the folder map's {len(mapped)} folders are the repository's")
