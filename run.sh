#!/usr/bin/env bash
# Installs what is missing, builds, and renders the built-in default scene with its report, on the
# SVO core and on the BVH core.
set -euo pipefail
cd "$(dirname "$0")"
source scripts/setup.sh
mkdir -p out
# Without arguments, the frame with its shadow and ambient-occlusion passes (docs/workloads.md).
passes=()
(($# == 0)) && passes=(--passes primary,shadow,ao --samples 4)
./build/rtusim render --image out/default.png --cost-image out/default_cost.png \
  ${passes[@]+"${passes[@]}"} "$@"
# The default scene on a triangle core (issue 28): its voxel faces at depth 7 (1.7 M triangles;
# depth 8's 14 M take a minute to build) in a BVH, traced by the BVH core.
echo
./build/rtusim render --core bvh --depth 7 --image out/default_bvh.png \
  --cost-image out/default_bvh_cost.png
echo
# The animated default scene (docs/scenes.md): frames, animation.webp and a frame-rate plot.
./build/rtusim animate --scene-file scenes/default.toml --out-dir out/animation
