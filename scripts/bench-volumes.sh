#!/usr/bin/env bash
# Volume rendering and particles at 1920x1080 (facet bench's particles-100k
# and volume-* scenes), then facet's marching cubes against VTK's flying
# edges and marching cubes filters on the same 256^3 Marschner-Lobb volume
# and iso value, in this one script: the ratio is of medians taken in the
# same run. Installs python3-vtk9 (the peer only; the build does not need it).
set -euo pipefail
cd "$(dirname "$0")/.."
for p in python3-vtk9 python3-numpy; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || \
    { [ "$(id -u)" -eq 0 ] && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$p" >/dev/null; }
done
./scripts/build.sh
threads=${THREADS:-$(nproc)}
out=$(mktemp)
./build/app/facet bench --scenes particles-100k,volume-raycast-256,volume-splat-256,volume-isosurface-256 --size 1920x1080 \
  --threads "$threads" --frames "${FRAMES:-3}" --warmup 1 --no-memory --startup-runs 0 | tee "$out"
echo
echo "marching cubes on the 256^3 Marschner-Lobb volume at iso 0.5, facet against VTK, each with its own default threads"
./build/app/facet bench --scenes volume-isosurface-256 --size 64x64 --threads 1 --frames "${FRAMES:-3}" --warmup 0 --no-memory --startup-runs 0 \
  --backends cpu | grep "marching cubes:" | sed 's/^ */facet /' | tee -a "$out"
/usr/bin/python3 scripts/vtk_marching_cubes.py 256 0.5 "${FRAMES:-3}" | tee -a "$out"
facet_ms=$(grep "^facet marching cubes:" "$out" | sed -E 's/.* in ([0-9.]+) ms.*/\1/')
for filter in "flying edges" "marching cubes"; do
  vtk_ms=$(grep "^vtk $filter:" "$out" | sed -E 's/.* in ([0-9.]+) ms.*/\1/')
  awk -v f="$facet_ms" -v v="$vtk_ms" -v name="$filter" 'BEGIN { printf "facet / vtk %s: %.2f (time ratio; below 1: facet faster)\n", name, f / v }'
done
rm -f "$out"
