#!/usr/bin/env bash
# Renders every glTF 2.0 file that Debian's assimp-testmodels ships (or the
# folder in FACET_SAMPLE_MODELS) twice, with the default shading (phong) and
# with --set shading=pbr, for a side-by-side look at the results.
#
#   scripts/sample_models.sh [FACET [OUT_DIR [EXTRA facet render ARGS...]]]
#   defaults: build/app/facet  build/sample_models
#   e.g.      scripts/sample_models.sh build/app/facet build/sample_models --backend cpu
#
# Writes OUT_DIR/<relative path with / as _, no extension>_{phong,pbr}.png,
# OUT_DIR/logs/<same>_{phong,pbr}.stderr and OUT_DIR/summary.tsv (one row per
# file and mode: file, mode, exit code, png written, status, stderr's first line).
#
# Some of the files are broken on purpose: facet refusing one with exit code 1
# (and one error line) is the expected outcome. The script fails (exit 1) only
# if facet crashes or hangs (any exit code other than 0 and 1), leaves a PNG
# behind after failing, or succeeds without writing one.
set -euo pipefail

root="$(cd "$(dirname "$0")/.." && pwd)"
facet="${1:-$root/build/app/facet}"
out="${2:-$root/build/sample_models}"
if (($# > 2)); then shift 2; else shift $#; fi
extra=("$@")
models="${FACET_SAMPLE_MODELS:-/usr/share/assimp/models/glTF2}"
size="${FACET_SAMPLE_SIZE:-320x320}"
limit="${FACET_SAMPLE_TIMEOUT:-300}" # seconds per render

[[ -x "$facet" ]] || { echo "sample_models.sh: no facet binary at '$facet' (build first, or pass its path)" >&2; exit 64; }
[[ -d "$models" ]] || { echo "sample_models.sh: no models folder '$models' (apt-get install assimp-testmodels)" >&2; exit 64; }
facet="$(cd "$(dirname "$facet")" && pwd)/$(basename "$facet")"

mkdir -p "$out/logs"
summary="$out/summary.tsv"
printf 'file\tmode\texit\tpng\tstatus\tstderr_first_line\n' >"$summary"

files=()
while IFS= read -r -d '' f; do files+=("${f#./}"); done < <(
  cd "$models" && find . -type f \( -iname '*.gltf' -o -iname '*.glb' \) -print0 | LC_ALL=C sort -z)
((${#files[@]} > 0)) || { echo "sample_models.sh: no .gltf/.glb files under '$models'" >&2; exit 1; }

timeout_cmd=()
if command -v timeout >/dev/null; then timeout_cmd=(timeout "$limit"); fi

declare -A seen=()
problems=0 ok=0 refused=0
for rel in "${files[@]}"; do
  name="${rel%.*}"
  name="${name//\//_}"
  if [[ -n "${seen[$name]:-}" ]]; then
    echo "sample_models.sh: '$rel' and '${seen[$name]}' map to the same name '$name'" >&2
    exit 1
  fi
  seen[$name]="$rel"
  for mode in phong pbr; do
    png="$out/${name}_${mode}.png"
    log="$out/logs/${name}_${mode}.stderr"
    rm -f "$png"
    args=(render "$models/$rel" -o "$png" --size "$size")
    [[ "$mode" == pbr ]] && args+=(--set shading=pbr)
    ((${#extra[@]} > 0)) && args+=("${extra[@]}")
    rc=0
    "${timeout_cmd[@]}" "$facet" "${args[@]}" >/dev/null 2>"$log" </dev/null || rc=$?
    first="$(head -n 1 "$log" | tr '\t\r' '  ')"
    wrote=no
    [[ -s "$png" ]] && wrote=yes
    [[ -e "$png" && ! -s "$png" ]] && wrote=empty
    case "$rc:$wrote" in
      0:yes) status=ok; ok=$((ok + 1)) ;;
      0:*) status=NO_PNG; problems=$((problems + 1)) ;;
      1:no) status=refused; refused=$((refused + 1)) ;;
      1:*) status=PNG_AFTER_FAILURE; problems=$((problems + 1)) ;;
      124:*) status=TIMEOUT; problems=$((problems + 1)) ;;
      *) status=CRASH; problems=$((problems + 1)) ;;
    esac
    printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$rel" "$mode" "$rc" "$wrote" "$status" "$first" >>"$summary"
    if [[ "$status" != ok && "$status" != refused ]]; then
      echo "sample_models.sh: $rel ($mode): $status, exit $rc: $first" >&2
    fi
  done
done

echo "sample_models.sh: ${#files[@]} files, $((ok + refused + problems)) renders: $ok ok, $refused refused (exit 1, no PNG), $problems problems; see $summary"

# Contact sheets, one per mode, every file a labelled tile (a dark red blank for
# a file facet refused), if ImageMagick's montage is there. Optional: a failure
# here is reported but does not fail the run.
if command -v montage >/dev/null; then
  for mode in phong pbr; do
    tiles=()
    for rel in "${files[@]}"; do
      name="${rel%.*}"
      name="${name//\//_}"
      png="$out/${name}_${mode}.png"
      dir="$(dirname "$rel")"
      label="$dir"$'\n'"$(basename "$rel")"
      if [[ -s "$png" ]]; then
        tiles+=(-label "$label" "$png")
      else
        rc="$(awk -F'\t' -v f="$rel" -v m="$mode" '$1 == f && $2 == m { print $3 }' "$summary")"
        tiles+=(-label "$label"$'\n'"(no image, exit $rc)" "xc:#401010")
      fi
    done
    if montage -font DejaVu-Sans -pointsize 9 -size "$size" "${tiles[@]}" -tile 8x -geometry 240x240+4+4 \
      -background '#777777' -fill black "$out/sheet_${mode}.png"; then
      echo "sample_models.sh: contact sheet $out/sheet_${mode}.png"
    else
      echo "sample_models.sh: montage failed; no $out/sheet_${mode}.png" >&2
    fi
  done
fi

((problems == 0))
