#!/usr/bin/env bash
# Installs what is missing, builds, and renders the built-in default scene with its report.
set -euo pipefail
cd "$(dirname "$0")"
source scripts/setup.sh
mkdir -p out
# Without arguments, the frame with its shadow and ambient-occlusion passes (docs/workloads.md).
passes=()
(($# == 0)) && passes=(--passes primary,shadow,ao --samples 4)
./build/rtusim render --image out/default.png --cost-image out/default_cost.png \
  ${passes[@]+"${passes[@]}"} "$@"
# The animated default scene (docs/scenes.md): frames, animation.webp and a frame-rate plot.
./build/rtusim animate --scene-file scenes/default.toml --out-dir out/animation
