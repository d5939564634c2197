#!/usr/bin/env bash
# facet batch against separate facet render processes, on the same machine
# in the same run: N frames at 256x256 (default 500) over the default scene
# and a few of assimp's glTF test models, cycling through them with the CPU
# backend. Prints each side's wall time, peak memory (GNU time's maximum
# resident set size; for the processes, the largest of any one) and the ratio.
#   scripts/batch_bench.sh [N] [FACET]   (FACET default: build/app/facet)
set -euo pipefail
cd "$(dirname "$0")/.."
n=${1:-500}
facet=$(realpath "${2:-build/app/facet}")
models=/usr/share/assimp/models/glTF2
scenes=(builtin:default "$models/BoxTextured-glTF/BoxTextured.gltf" "$models/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"
        "$models/BoxTextured-glTF-Binary/BoxTextured.glb" "$models/ClearCoat-glTF/ClearCoatTest.gltf")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
usable=()
for scene in "${scenes[@]}"; do  # a model that does not render here is left out, not counted
  if "$facet" render "$scene" --backend cpu --size 32x32 -o "$work/probe.png" >/dev/null 2>&1; then usable+=("$scene"); fi
done
echo "scenes: ${usable[*]}"
for ((k = 0; k < n; ++k)); do
  printf '{"scene":"%s","size":"256x256","backend":"cpu","output":"batch/%d.png"}\n' "${usable[k % ${#usable[@]}]}" "$k"
done >"$work/jobs.jsonl"

/usr/bin/time -f '%e %M' -o "$work/batch.time" "$facet" batch "$work/jobs.jsonl" >"$work/batch.log"
read -r batch_s batch_kb <"$work/batch.time"

mkdir -p "$work/render"
start=$(date +%s.%N)
peak=0
for ((k = 0; k < n; ++k)); do
  /usr/bin/time -f '%M' -o "$work/one.time" "$facet" render "${usable[k % ${#usable[@]}]}" --backend cpu --size 256x256 -o "$work/render/$k.png" >/dev/null
  kb=$(<"$work/one.time")
  ((kb > peak)) && peak=$kb
done
end=$(date +%s.%N)
render_s=$(echo "$end - $start" | bc)

printf '%-34s %10s %14s\n' "" "wall s" "peak RSS MiB"
printf '%-34s %10.2f %14.1f\n' "facet batch ($n jobs, one process)" "$batch_s" "$(echo "$batch_kb / 1024" | bc -l)"
printf '%-34s %10.2f %14.1f\n' "$n facet render processes" "$render_s" "$(echo "$peak / 1024" | bc -l)"
printf 'separate processes / batch: %.2fx the wall time\n' "$(echo "$render_s / $batch_s" | bc -l)"
