#!/usr/bin/env bash
# Re-creates the agreement suite's golden images (CPU renders at 256x256) on
# purpose, after a change that is meant to change images. Review the new
# PNGs (git diff --stat tests/agreement/golden) before committing them.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
./build/tests/agreement/facet_agreement --cases tests/agreement/cases --golden tests/agreement/golden \
  --out build/agreement --update-goldens
# The ray tracer's goldens (tests/ray/goldens.txt: name, scene, settings).
grep -E '^[a-z]' tests/ray/goldens.txt | while read -r name scene settings; do
  # shellcheck disable=SC2086  # the settings are words
  ./build/app/facet render "$scene" --backend ray --size 240x180 $settings -o "tests/ray/golden/$name.png" >/dev/null
done
