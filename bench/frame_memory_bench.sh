#!/usr/bin/env bash
# Peak resident memory of `rtusim render` against the frame's size (issue 33, "Memory bounded by
# the work"): 1280x720, 1920x1080, 3840x2160 and 7680x4320 on every model (golden, lt, ca), on
# the SVO default scene and on the BVH core over a depth-6 sphere's voxel faces (the default scene's
# voxel faces make a BVH of 2.8 GB, whatever the frame), no images asked; then the SVO core with a
# shaded PNG image (`images png`, written row by row as the results leave the run) and with the
# depth and cost images too (`images all`, which keep 12 bytes a pixel for their scales). The
# records are made as the run asks for them and the results taken as they leave it, so every
# model's peak follows the scene and the simulated RTU, not the frame (docs/robustness.md,
# "Memory").
# Usage: bench/frame_memory_bench.sh [path/to/rtusim] [sizes...]   (sizes as WxH)
# Figures are recorded in docs/performance.md, section "Frame memory".
set -euo pipefail

rtusim=${1:-$(dirname "$0")/../build/rtusim}
shift || true
sizes=("$@")
((${#sizes[@]})) || sizes=(1280x720 1920x1080 3840x2160 7680x4320)
[[ -x $rtusim ]] || { echo "frame_memory_bench: '$rtusim' is not an executable" >&2; exit 1; }
[[ -x /usr/bin/time ]] || { echo "frame_memory_bench: needs GNU time (/usr/bin/time)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# measure CORE MODEL SIZE IMAGES [render options...]
measure() {
  local core=$1 model=$2 size=$3 images=$4
  shift 4
  local width=${size%x*} height=${size#*x} kib seconds
  if /usr/bin/time -f '%M %U' -o "$work/time" "$rtusim" render --core "$core" --model "$model" \
    --width "$width" --height "$height" "$@" >/dev/null 2>"$work/err"; then
    read -r kib seconds <"$work/time"
    printf '%-5s %-7s %-10s %-7s %10d %10.1f %12.2f\n' "$core" "$model" "$size" "$images" \
      $((width * height)) "$(awk -v k="$kib" 'BEGIN { print k / 1024 }')" "$seconds"
  else
    printf '%-5s %-7s %-10s %-7s %10d   refused: %s\n' "$core" "$model" "$size" "$images" \
      $((width * height)) "$(tail -1 "$work/err")"
  fi
}

printf '%-5s %-7s %-10s %-7s %10s %10s %12s\n' core model frame images rays "peak MB" "CPU s"
for core in svo bvh; do
  scene=()
  [[ $core == bvh ]] && scene=(--scene sphere --depth 6)
  for model in golden lt ca; do
    for size in "${sizes[@]}"; do
      measure "$core" "$model" "$size" none "${scene[@]}"
    done
  done
done
for model in golden lt ca; do
  for size in "${sizes[@]}"; do
    measure svo "$model" "$size" png --image "$work/frame.png"
    measure svo "$model" "$size" all --image "$work/frame.png" --depth-image "$work/depth.png" \
      --cost-image "$work/cost.png"
  done
done
