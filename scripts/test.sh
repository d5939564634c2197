#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test. This is what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh "$@"
ctest --test-dir "${FACET_BUILD_DIR:-build}" --output-on-failure --parallel "$(nproc)"
