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
formats=16.8,16.12,20.12,20.16,24.12,24.16,24.20,28.16,28.20,28.24,32.16,32.20,32.24,32.28,40.20,40.28,40.32,48.24,48.32,48.40
size=(--width 256 --height 256)

run() {  # name, then the scene options
  local name=$1
  shift
  echo "== $name"
  "$rtusim" precision "$@" "${size[@]}" --formats "$formats" --csv "$out/$name.csv" \
    --images "$out/images_$name"
}
for scene in sphere shell menger terrain noise; do
  mkdir -p "$out/images_${scene}_8"
  run "${scene}_8" --scene "$scene" --depth 8
done
for depth in 6 10 12; do
  mkdir -p "$out/images_sphere_$depth"
  run "sphere_$depth" --scene sphere --depth "$depth"
done
mkdir -p "$out/images_spider_8"
run spider_8 --mesh "$mesh" --depth 8
/usr/bin/python3 scripts/precision_plot.py "$out"
