#!/usr/bin/env bash
# Issue 28 §4's speed targets on a 1280x720 frame of the CGAL bunny (bunny00, 75,408 triangles),
# BVH core: the cycle-accurate RTU at 16 cores no slower than 4 times the golden traversal with
# ideal memory and 8 times cached, the loosely-timed model at least a quarter of golden's speed,
# and 1024 cores within 1.5 times 16. Each configuration is `rtusim render` of the whole frame;
# its frame time is its CPU seconds (user + system, GNU time) less those of the same command on an
# 8x8 frame (the mesh read and the BVH build, which every configuration shares), the least of
# `runs` runs, the configurations alternating so that a drifting machine load treats them alike.
# Usage: bench/triangle_speed.sh [runs] [rtusim]     (default: 5 runs of build/rtusim)
# Figures are recorded in docs/performance.md, "Issue 28's speed targets".
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
runs=${1:-5}
rtusim=${2:-$root/build/rtusim}
[[ -x $rtusim ]] || { echo "triangle_speed: '$rtusim' is not an executable" >&2; exit 1; }
[[ -x /usr/bin/time ]] || { echo "triangle_speed: needs GNU time (/usr/bin/time)" >&2; exit 1; }
bunny=$("$root/bench/cgal_meshes.sh" bunny00)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

names=(load golden "ca 16" "ca 16 cached" "lt 16" "lt 16 cached" "ca 1024")
frame="--width 1280 --height 720"
configs=("--model golden --width 8 --height 8" "--model golden $frame"
         "--model ca --cores 16 $frame" "--model ca --cores 16 --preset cached $frame"
         "--model lt --cores 16 $frame" "--model lt --cores 16 --preset cached $frame"
         "--model ca --cores 1024 $frame")
declare -A best
for ((i = 0; i < runs; ++i)); do
  for c in "${!configs[@]}"; do
    # shellcheck disable=SC2086  # the configuration's words are options
    /usr/bin/time -f '%U %S' -o "$work/time" "$rtusim" render --core bvh --mesh "$bunny" \
      ${configs[$c]} >/dev/null 2>&1
    seconds=$(awk '{ print $1 + $2 }' "$work/time")
    if [[ -z ${best[$c]:-} ]] || awk -v a="$seconds" -v b="${best[$c]}" 'BEGIN { exit !(a < b) }'; then
      best[$c]=$seconds
    fi
  done
done
load=${best[0]}
golden=$(awk -v a="${best[1]}" -v l="$load" 'BEGIN { print a - l }')
printf '%-14s %10s %10s %14s\n' configuration "CPU s" "frame s" "/ golden"
for c in "${!configs[@]}"; do
  awk -v n="${names[$c]}" -v s="${best[$c]}" -v l="$load" -v g="$golden" -v c="$c" 'BEGIN {
    f = c == 0 ? s : s - l
    printf "%-14s %10.3f %10.3f %14s\n", n, s, f, c == 0 ? "" : sprintf("%.2f", f / g) }'
done
