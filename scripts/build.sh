#!/usr/bin/env bash
# Configures and builds facet into ./build (Release, all cores).
# Extra arguments go to the CMake configure step, e.g. -DFACET_SANITIZE=ON.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B "${FACET_BUILD_DIR:-build}" -DCMAKE_BUILD_TYPE="${FACET_BUILD_TYPE:-Release}" "$@" >/dev/null
cmake --build "${FACET_BUILD_DIR:-build}" --parallel "$(nproc)"
