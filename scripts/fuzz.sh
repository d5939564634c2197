#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) into build-fuzz and
# runs each for SECONDS (default 60) from its seed corpus. A crash leaves its
# input in build-fuzz/findings and fails; turn it into a regression test by
# copying it to tests/fuzz/regressions/TARGET/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
./scripts/install-deps.sh
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFACET_BUILD_FUZZERS=ON \
  -DFACET_BUILD_GL=OFF -DFACET_BUILD_TESTS=OFF >/dev/null
targets=(gltf_loader cpu_rasterizer png_reader settings_json)
cmake --build build-fuzz --parallel "$(nproc)" --target "${targets[@]/#/fuzz_}"
mkdir -p build-fuzz/findings
for target in "${targets[@]}"; do
  corpus="build-fuzz/corpus/$target"
  mkdir -p "$corpus"
  cp -n tests/fuzz/corpus/"$target"/* tests/fuzz/regressions/"$target"/* "$corpus"/ 2>/dev/null || true
  echo "fuzz_$target: $seconds s"
  "build-fuzz/tests/fuzz/fuzz_$target" -max_total_time="$seconds" -rss_limit_mb=4096 -max_len=65536 \
    -artifact_prefix=build-fuzz/findings/"$target"- -print_final_stats=1 "$corpus" 2>&1 |
    grep -E '^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ +DONE)|ERROR|SUMMARY|runtime error' || true
  if ls build-fuzz/findings/"$target"-* >/dev/null 2>&1; then
    echo "fuzz_$target found a crash: $(ls build-fuzz/findings/"$target"-*)" >&2
    exit 1
  fi
done
