#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) into build-fuzz and
# runs each for SECONDS (default 60) from its seed corpus, one per core at a
# time. FACET_FUZZ_BUILD_DIR=build-sanitize runs them from the sanitizer
# build instead (scripts/sanitize.sh builds them there), with no build of
# their own. A crash leaves its input in BUILD/findings and fails; turn it
# into a regression test by copying it to tests/fuzz/regressions/TARGET/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
./scripts/install-deps.sh
build="${FACET_FUZZ_BUILD_DIR:-build-fuzz}"
if [ ! -f "$build/CMakeCache.txt" ]; then
  # -O1 and line tables, as for the sanitizer run (scripts/sanitize.sh).
  CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFACET_BUILD_FUZZERS=ON \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DFACET_BUILD_GL=OFF -DFACET_BUILD_TESTS=OFF >/dev/null
elif ! grep -q '^FACET_BUILD_FUZZERS:BOOL=ON' "$build/CMakeCache.txt"; then
  echo "fuzz: $build is not configured with FACET_BUILD_FUZZERS=ON" >&2
  exit 64
fi
targets=(gltf_loader cpu_rasterizer png_reader settings_json)
cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]/#/fuzz_}"
mkdir -p "$build/findings"
# fuzz_one TARGET: runs one target from its corpus, its summary lines into
# BUILD/TARGET.log.
fuzz_one() {
  local target=$1
  local corpus="$build/corpus/$target"
  mkdir -p "$corpus"
  cp -n tests/fuzz/corpus/"$target"/* tests/fuzz/regressions/"$target"/* "$corpus"/ 2>/dev/null || true
  "$build/tests/fuzz/fuzz_$target" -max_total_time="$seconds" -rss_limit_mb=4096 -max_len=65536 \
    -artifact_prefix="$build/findings/$target-" -print_final_stats=1 "$corpus" 2>&1 |
    grep -E '^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ +DONE)|ERROR|SUMMARY|runtime error' \
      >"$build/$target.log" || true
}
# One target per core at a time: each fuzzer is single-threaded.
running=0
for target in "${targets[@]}"; do
  echo "fuzz_$target: $seconds s"
  fuzz_one "$target" &
  running=$((running + 1))
  if [ "$running" -ge "$(nproc)" ]; then
    wait -n || true
    running=$((running - 1))
  fi
done
wait
status=0
for target in "${targets[@]}"; do
  echo "fuzz_$target:"
  cat "$build/$target.log"
  if ls "$build/findings/$target-"* >/dev/null 2>&1; then
    echo "fuzz_$target found a crash: $(ls "$build/findings/$target-"*)" >&2
    status=1
  fi
done
exit "$status"
