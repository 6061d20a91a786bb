#!/usr/bin/env bash
# The precision study of docs/precision.md: `rtusim precision` over word widths from 16 to 48 bits
# with several fraction splits, on every procedural scene at depth 8, the sphere at depths 6 to 12,
# and the assimp spider mesh; then the plot of error rate against word width.
#   scripts/precision_study.sh [output directory, default out/precision] [rtusim binary]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/precision}
rtusim=${2:-build/rtusim}
source scripts/spider_mesh.sh
mkdir -p "$out"
formats=Q8.8,Q4.12,Q8.12,Q4.16,Q12.12,Q8.16,Q4.20,Q12.16,Q8.20,Q4.24,Q16.16,Q12.20,Q8.24,Q4.28,Q20.20,Q12.28,Q8.32,Q24.24,Q16.32,Q8.40
size=(--width 256 --height 256)

run() {  # name, then the scene options
  local name=$1
  shift
  echo "== $name"
  "$rtusim" precision "$@" "${size[@]}" --formats "$formats" --csv "$out/$name.csv" \
    --images "$out/images_$name"
}
for scene in sphere shell menger terrain noise; do
  run "${scene}_8" --scene "$scene" --depth 8
done
for depth in 6 10 12; do
  run "sphere_$depth" --scene sphere --depth "$depth"
done
run spider_8 --mesh "$mesh" --depth 8
/usr/bin/python3 scripts/precision_plot.py "$out"
