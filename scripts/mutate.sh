#!/usr/bin/env bash
# Breaks facet on purpose, one mutation at a time (scripts/mutations.txt),
# and reports how many ctest entries fail for each and whether one of them
# is named for the broken feature. Works on a copy of the tree in
# ${FACET_MUTATE_DIR:-build-mutate}/src with its own build, so the working
# tree is never touched.
#   scripts/mutate.sh [REGEX]     only the mutations whose name matches REGEX
# Each case of the agreement suite is its own ctest entry, agreement:CASE,
# so that a mutation can be held to the cases of its feature. Prints a
# Markdown table (and writes every failing entry of each mutation to
# failing.txt beside the copy);
# exits 1 when a mutation does not apply or when no test named for its
# feature fails.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
work=$(realpath -m "${FACET_MUTATE_DIR:-build-mutate}")
filter="${1:-}"
src="$work/src" build="$work/build"
rm -rf "$src"
mkdir -p "$src" "$build"
git ls-files -co --exclude-standard -z | tar --null -T - -cf - | tar -xf - -C "$src"
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --parallel "$(nproc)" >/dev/null
echo "baseline: $(ctest --test-dir "$build" --parallel "$(nproc)" 2>&1 | grep -E 'tests passed' || true)" >&2

# Applies (or, with restore, puts back) one mutation's edits.
declare -a files froms tos
apply() {
  local i
  for i in "${!files[@]}"; do
    cp "$src/${files[$i]}" "$work/original.$i"
    FROM="${froms[$i]}" TO="${tos[$i]}" perl -0pi -e '$n += s/\Q$ENV{FROM}\E/$ENV{TO}/g; END { exit($n ? 0 : 3) }' "$src/${files[$i]}" ||
      { echo "mutation '$name': '${froms[$i]}' not found in ${files[$i]}" >&2; return 1; }
  done
}
restore() {
  local i
  for i in "${!files[@]}"; do cp "$work/original.$i" "$src/${files[$i]}"; done
}

status=0
: >"$work/failing.txt"
echo "| mutation | failing ctest entries | failing agreement cases | named for it | verdict |"
echo "| --- | --- | --- | --- | --- |"
run() {
  [ -z "$name" ] && return 0
  if [ -n "$filter" ] && ! [[ "$name" =~ $filter ]]; then return 0; fi
  if ! apply; then
    restore
    echo "| $name | - | - | - | DID NOT APPLY |"
    status=1
    return 0
  fi
  local log="$work/last.log" failing=0 cases=0 named=0 names=""
  if cmake --build "$build" --parallel "$(nproc)" >"$log" 2>&1; then
    ctest --test-dir "$build" --parallel "$(nproc)" --output-on-failure >"$log" 2>&1 || true
    echo "## $name" >>"$work/failing.txt"
    while IFS= read -r test; do
      echo "$test" >>"$work/failing.txt"
      if [[ "$test" == agreement:* ]]; then cases=$((cases + 1)); else failing=$((failing + 1)); fi
      if [[ "$test" =~ $expect ]]; then
        named=$((named + 1))
        [ ${#names} -lt 160 ] && names="$names${names:+; }$test"
      fi
    done < <(sed -n 's/^[[:space:]]*[0-9]* - \(.*\) (\(Failed\|SEGFAULT\|Subprocess aborted\|Timeout\|Exception\|Child aborted\|Not Run\|\*\*\*.*\))$/\1/p' "$log")
  else
    failing="build" cases="-" named=1 names="the build fails"
  fi
  restore
  local verdict=caught
  [ "$named" -eq 0 ] && { verdict=MISSED; status=1; }
  echo "| $name | $failing | $cases | $named: ${names:-none} | $verdict |"
}

name="" expect=""
files=() froms=() tos=()
while IFS= read -r line || [ -n "$line" ]; do
  case "$line" in
    "#"* | "") ;;
    "name: "*) run; name="${line#name: }"; expect=""; files=(); froms=(); tos=() ;;
    "file: "*) files+=("${line#file: }") ;;
    "from: "*) froms+=("${line#from: }") ;;
    "to: "*) tos+=("${line#to: }") ;;
    "expect: "*) expect="${line#expect: }" ;;
    *) echo "mutations.txt: cannot read: $line" >&2; exit 64 ;;
  esac
done < "$root/scripts/mutations.txt"
run
# The copy is built unmutated again, so that the next run starts clean.
cmake --build "$build" --parallel "$(nproc)" >/dev/null
exit $status
