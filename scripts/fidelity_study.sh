#!/usr/bin/env bash
# The fidelity study of docs/fidelity.md: `rtusim fidelity` (SystemC, recurrence, loosely-timed at
# two quanta, sampled at three fractions, golden) on 1280x720 frames of every procedural scene at
# depth 8 and the assimp spider mesh, 16 cores with the `cached` preset's memory; menger at 1, 4
# and 64 cores; menger and noise with ideal memory. Then the plot of error against speed-up.
#   scripts/fidelity_study.sh [output directory, default out/fidelity] [rtusim binary]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/fidelity}
rtusim=${2:-build/rtusim}
source scripts/spider_mesh.sh
mkdir -p "$out"
common=(--width 1280 --height 720 --quanta 1000,100000 --fractions 0.05,0.1,0.2 --sample-seed 1)

run() {  # name, then the configuration's options
  local name=$1
  shift
  echo "== $name"
  "$rtusim" fidelity "$@" "${common[@]}" --csv "$out/$name.csv" | tee "$out/$name.txt"
}
for scene in menger sphere shell terrain noise; do
  run "cached_${scene}_16" --preset cached --scene "$scene" --depth 8 --cores 16
done
run cached_spider_16 --preset cached --mesh "$mesh" --depth 8 --cores 16
for cores in 1 4 64; do
  run "cached_menger_$cores" --preset cached --scene menger --depth 8 --cores "$cores"
done
for scene in menger noise; do
  run "ideal_${scene}_16" --preset cached --memory ideal --scene "$scene" --depth 8 --cores 16
done
/usr/bin/python3 scripts/fidelity_plot.py docs/images/fidelity_error_vs_speedup.png "$out"/*.csv
