"""Every ctest entry carries exactly one tier label (quick or long) and at
least one area label, and no label outside those (tests/labels.cmake), so
that an entry added without them cannot slip out of `ctest -L quick`, out of
scripts/sanitize.sh's shards, or out of its area.
    check_labels.py CTEST BUILD_FOLDER TIERS AREAS   (TIERS, AREAS: comma-separated)"""
import json
import subprocess
import sys

ctest, build, tiers, areas = sys.argv[1], sys.argv[2], set(sys.argv[3].split(",")), set(sys.argv[4].split(","))
listing = subprocess.run([ctest, "--test-dir", build, "-N", "--show-only=json-v1"], check=True, capture_output=True, text=True).stdout
problems = []
tests = json.loads(listing)["tests"]
for test in tests:
    labels = next((p["value"] for p in test.get("properties", []) if p["name"] == "LABELS"), [])
    its_tiers = [label for label in labels if label in tiers]
    its_areas = [label for label in labels if label in areas]
    unknown = [label for label in labels if label not in tiers and label not in areas]
    if len(its_tiers) != 1:
        problems.append(f"{test['name']}: tiers {its_tiers or 'none'} (one of {', '.join(sorted(tiers))})")
    if not its_areas:
        problems.append(f"{test['name']}: no area (one or more of {', '.join(sorted(areas))})")
    if unknown:
        problems.append(f"{test['name']}: unknown labels {unknown} (tests/labels.cmake lists the tiers and areas)")
for problem in problems:
    print(problem)
print(f"{len(tests)} entries, {len(problems)} problems")
sys.exit(1 if problems else 0)
