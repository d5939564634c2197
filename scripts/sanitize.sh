#!/usr/bin/env bash
# Builds facet with AddressSanitizer and UndefinedBehaviorSanitizer (GCC,
# plus -fsanitize=float-cast-overflow, which GCC's UBSan leaves out) into
# build-sanitize and runs the whole test suite there. Any report fails.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
FACET_BUILD_DIR=build-sanitize FACET_BUILD_TYPE=RelWithDebInfo ./scripts/build.sh -DFACET_SANITIZE=ON
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"
ctest --test-dir build-sanitize --output-on-failure --parallel "$(nproc)" --timeout 1800
