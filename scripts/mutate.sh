#!/usr/bin/env bash
# Breaks facet on purpose, one mutation at a time (scripts/mutations.txt),
# and reports how many ctest entries fail for each and whether one of them
# is named for the broken feature. Works on a copy of the tree in
# ${FACET_MUTATE_DIR:-build-mutate}/src with its own build, so the working
# tree is never touched.
#   scripts/mutate.sh [REGEX]     only the mutations whose name matches REGEX
# Each mutation runs the quick tier and every entry its `expect` names (the
# tests of its feature, long ones included), not the whole suite;
# FACET_MUTATE_ALL=1 runs every entry for each. Each case of
# the agreement suite is its own entry, agreement:CASE, so that a mutation
# can be held to the cases of its feature. Prints a Markdown table (and
# writes every failing entry of each mutation to failing.txt beside the
# copy); exits 1 when a mutation does not apply, does not build, or when no
# test named for its feature fails. scripts/mutations.py parses
# mutations.txt and applies the edits; its --check (the ctest entry
# mutations.every_mutation_applies) catches a mutation that no longer
# applies in a second.
#
# Time, measured on 2 cores shared with another build (load 5 to 7), for
# five mutations: 38 to 204 s each, 106 s on average (the rebuild of what
# the edit reaches, the quick tier, and the long entries its expect names:
# every agreement case for a mutation of the lit pass); all 128, about 4
# hours. Before them, bringing the copy up to date, its build and a
# baseline run of the whole suite take about 7 minutes (the first run
# builds the copy from nothing: 35 minutes).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
work=$(realpath -m "${FACET_MUTATE_DIR:-build-mutate}")
filter="${1:-}"
mutations="python3 $root/scripts/mutations.py"
$mutations --check >&2 || exit 1  # every mutation applies, before an hour of building
src="$work/src" build="$work/build" stage="$work/stage"
# The copy is brought up to the working tree by content: a file that differs
# is copied, with a new time, so that make builds what depends on it; an
# equal one is left alone with the objects built from it. (Times copied
# from the tree would not do: a file edited while a run was building, or
# left mutated by a run that was stopped, is older than its objects.)
rm -rf "$stage"
mkdir -p "$src" "$build" "$stage"
git ls-files -co --exclude-standard -z | tar --null -T - -cf - | tar -xf - -C "$stage"
(cd "$stage" && find . -type f -print0) | while IFS= read -r -d '' file; do
  cmp -s "$stage/$file" "$src/$file" || { mkdir -p "$(dirname "$src/$file")" && cp "$stage/$file" "$src/$file"; }
done
(cd "$src" && find . -type f -print0) | while IFS= read -r -d '' file; do
  [ -e "$stage/$file" ] || rm "$src/$file"
done
rm -rf "$stage" "$work/backup"
launchers=()
if command -v ccache >/dev/null; then launchers=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache); fi
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release "${launchers[@]}" >/dev/null
cmake --build "$build" --parallel "$(nproc)" >/dev/null
echo "baseline: $(ctest --test-dir "$build" --parallel "$(nproc)" 2>&1 | grep -E 'tests passed' || true)" >&2

status=0
: >"$work/failing.txt"
echo "| mutation | failing ctest entries | failing agreement cases | named for it | verdict |"
echo "| --- | --- | --- | --- | --- |"
# The names come on descriptor 3: a test may read its standard input (script(1) does), which is /dev/null.
while IFS= read -r -u 3 name; do
  started=$SECONDS
  if ! $mutations --apply "$name" --root "$src" --backup "$work/backup" 2>/dev/null; then
    $mutations --restore --root "$src" --backup "$work/backup"
    echo "| $name | - | - | - | DID NOT APPLY |"
    status=1
    continue
  fi
  log="$work/last.log" failing=0 cases=0 named=0 names="" verdict=caught
  if cmake --build "$build" --parallel "$(nproc)" >"$log" 2>&1; then
    selection=()
    [ -n "${FACET_MUTATE_ALL:-}" ] || selection=(-I "$($mutations --select "$name" --build "$build")")
    ctest --test-dir "$build" --parallel "$(nproc)" --output-on-failure "${selection[@]}" >"$log" 2>&1 || true
    sed -n 's/^[[:space:]]*[0-9]* - \(.*\) (\(Failed\|SEGFAULT\|Subprocess aborted\|Timeout\|Exception\|Child aborted\|Not Run\|\*\*\*.*\))$/\1/p' "$log" \
      >"$work/failed.txt"
    { echo "## $name"; cat "$work/failed.txt"; } >>"$work/failing.txt"
    cases=$(grep -c '^agreement:' "$work/failed.txt" || true)
    failing=$(($(wc -l <"$work/failed.txt") - cases))
    names=$($mutations --named "$name" <"$work/failed.txt")
    named=$(grep -c . <<<"$names" || true)
    names=${names//$'\n'/; }
    [ ${#names} -gt 160 ] && names="${names:0:160}..."
    [ "$named" -eq 0 ] && { verdict=MISSED; status=1; }
  else
    failing="build" cases="-" verdict="DOES NOT BUILD" status=1
  fi
  $mutations --restore --root "$src" --backup "$work/backup"
  echo "| $name | $failing | $cases | $named: ${names:-none} | $verdict ($((SECONDS - started)) s) |"
done 3< <($mutations --list "$filter") </dev/null
# The copy is built unmutated again, so that the next run starts clean.
cmake --build "$build" --parallel "$(nproc)" >/dev/null
exit $status
