#!/usr/bin/env bash
# Peak resident memory of `rtusim render` against the frame's size (issue 33, "Memory bounded by
# the work"): 1280x720, 1920x1080, 3840x2160 and 7680x4320 on every model (golden, lt, ca), on
# the SVO default scene and on the BVH core over a depth-6 sphere's voxel faces (the default scene's
# voxel faces make a BVH of 2.8 GB, whatever the frame), no images asked. The records are made as the run asks
# for them and the results taken as they leave it, so the golden and cycle-accurate models' peak
# follows the scene and the simulated RTU, not the frame; the loosely-timed model still keeps its
# results and recurrence per ray (docs/robustness.md, "Memory").
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

printf '%-5s %-7s %-10s %10s %10s %12s\n' core model frame rays "peak MB" "CPU s"
for core in svo bvh; do
  scene=()
  [[ $core == bvh ]] && scene=(--scene sphere --depth 6)
  for model in golden lt ca; do
    for size in "${sizes[@]}"; do
      width=${size%x*} height=${size#*x}
      if /usr/bin/time -f '%M %U' -o "$work/time" "$rtusim" render --core "$core" "${scene[@]}" --model "$model" \
        --width "$width" --height "$height" >/dev/null 2>"$work/err"; then
        read -r kib seconds <"$work/time"
        printf '%-5s %-7s %-10s %10d %10.1f %12.2f\n' "$core" "$model" "$size" \
          $((width * height)) "$(awk -v k="$kib" 'BEGIN { print k / 1024 }')" "$seconds"
      else
        printf '%-5s %-7s %-10s %10d   refused: %s\n' "$core" "$model" "$size" \
          $((width * height)) "$(tail -1 "$work/err")"
      fi
    done
  done
done
