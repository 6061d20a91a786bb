#!/usr/bin/env bash
# The triangle formats' study of docs/precision.md, "Triangle formats": `rtusim precision
# --triangles` with its default sweep and ray sets on the CGAL Chinese dragon (bench/cgal_meshes.sh
# fetches it), the assimp spider (assimp-testmodels) and the menger sponge's voxel faces at
# depth 3 (axis-aligned triangles on the scene box), each with seed 004's stress triangle.
#   scripts/triangle_precision_study.sh [output directory, default out/triangle_precision]
#                                        [rtusim binary]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/triangle_precision}
rtusim=${2:-build/rtusim}
mkdir -p "$out"
dragon=$(bench/cgal_meshes.sh ChineseDragon-10kv)
"$rtusim" precision --triangles --mesh "$dragon" --csv "$out/dragon.csv" | tee "$out/dragon.txt"
"$rtusim" precision --triangles --mesh /usr/share/assimp/models/OBJ/spider.obj --drop-bad-triangles \
  --stress-size 0 --csv "$out/spider.csv" | tee "$out/spider.txt"
"$rtusim" precision --triangles --scene menger --depth 3 --stress-size 0 \
  --csv "$out/menger.csv" | tee "$out/menger.txt"
