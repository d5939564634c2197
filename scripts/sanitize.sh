#!/usr/bin/env bash
# Builds facet with clang's AddressSanitizer and UndefinedBehaviorSanitizer
# (with -fsanitize=float-cast-overflow) into build-sanitize and runs the
# quick tier of the test suite there, and one shard of the long tier
# (tests/labels.cmake). Any report fails. The same build holds the libFuzzer
# targets (FACET_BUILD_FUZZERS: libFuzzer's coverage on every library), which
# `FACET_FUZZ_BUILD_DIR=build-sanitize scripts/fuzz.sh` runs without a build
# of its own, as .ci/run does.
#
# The shard is the commit's hash modulo FACET_SANITIZE_SHARDS (4): one
# commit always runs the same shard, and every long entry runs under the
# sanitizers every few commits, at a quarter of the long tier's time.
# FACET_SANITIZE_SHARD=K runs shard K instead (the line printed below says
# which one ran); FACET_SANITIZE_SHARDS=1 runs the whole suite.
#
# Leaks are checked in every test but those that
# load a GL driver: beside llvmpipe's threads LeakSanitizer's exit-time
# tracer itself crashes now and then ("Tracer caught signal 11"), and Mesa's
# GLX driver is unloaded before exit, so its allocations could not be told
# from ours.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
# -O1 and line tables (-g1), as AddressSanitizer's documentation suggests:
# reports still name the function, file and line. clang, at -O1 -g1, builds
# the whole tree in well under half the time GCC took at -O2 -g
# (docs/testing.md gives the figures).
CC=clang CXX=clang++ FACET_BUILD_DIR=build-sanitize FACET_BUILD_TYPE=RelWithDebInfo ./scripts/build.sh -DFACET_BUILD_FUZZERS=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"

shards=${FACET_SANITIZE_SHARDS:-4}
commit=$(git rev-parse HEAD 2>/dev/null || echo 0)
shard=${FACET_SANITIZE_SHARD:-$((16#${commit:0:7} % shards))}
if ! [[ "$shard" =~ ^[0-9]+$ ]] || [ "$shard" -ge "$shards" ]; then
  echo "sanitize: FACET_SANITIZE_SHARD=$shard: expected 0 to $((shards - 1))" >&2
  exit 64
fi
echo "sanitize: the quick tier, and shard $shard of $shards of the long tier (commit ${commit:0:7}; FACET_SANITIZE_SHARD=$shard runs it again)"

# ctest over the quick tier, then over this shard of the long one (every
# shards-th entry by number, from the shard's own), with the arguments given.
run_tests() {
  ctest --test-dir build-sanitize --output-on-failure --parallel "$(nproc)" --timeout 1800 -L '^quick$' "$@"
  ctest --test-dir build-sanitize --output-on-failure --parallel "$(nproc)" --timeout 1800 -L '^long$' -I "$((shard + 1)),,$shards" "$@"
}
# One pass over the tests: those that load a GL driver run with leak
# checking off, every other one with it on.
loads_gl='^(gl\.|viewer\.|stages:|docs\.examples:|agreement(:|\.start$|\.summary$)|pathological|robustness\.|cli\.bench_(small|draws_maps_every_frame|keep_shadow_maps|lean_matches_cpu|sweep_quick)$|cli\.batch_jobs$)'
echo "sanitize: ASan + UBSan + LeakSanitizer on the tests that load no GL driver"
ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1" run_tests -E "$loads_gl"
echo "sanitize: ASan + UBSan on the tests that load a GL driver"
ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:strict_string_checks=1" run_tests -R "$loads_gl"
