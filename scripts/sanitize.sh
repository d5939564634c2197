#!/usr/bin/env bash
# Builds facet with AddressSanitizer and UndefinedBehaviorSanitizer (GCC,
# plus -fsanitize=float-cast-overflow, which GCC's UBSan leaves out) into
# build-sanitize and runs the whole test suite there. Any report fails.
#
# Leaks are checked in a second pass over the tests that load no GL driver:
# beside llvmpipe's threads LeakSanitizer's exit-time tracer itself crashes
# now and then ("Tracer caught signal 11"), and Mesa's GLX driver is
# unloaded before exit, so its allocations could not be told from ours.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
FACET_BUILD_DIR=build-sanitize FACET_BUILD_TYPE=RelWithDebInfo ./scripts/build.sh -DFACET_SANITIZE=ON
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
echo "sanitize: the whole suite under ASan + UBSan"
ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:strict_string_checks=1" \
  ctest --test-dir build-sanitize --output-on-failure --parallel "$(nproc)" --timeout 1800
echo "sanitize: LeakSanitizer on the tests that load no GL driver"
ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1" \
  ctest --test-dir build-sanitize --output-on-failure --parallel "$(nproc)" --timeout 1800 \
    -E '^(gl\.|viewer\.|stages:|agreement(:|\.start$|\.summary$)|pathological|robustness\.|cli\.bench_(small|draws_maps_every_frame|keep_shadow_maps|lean_matches_cpu|sweep_quick)$|cli\.batch_jobs$)'
