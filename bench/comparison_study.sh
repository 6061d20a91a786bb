#!/usr/bin/env bash
# Issue 30's study (docs/comparison.md, "The study"): `rtusim compare` on the CGAL meshes (bunny,
# armadillo, dragon, elephant: bench/cgal_meshes.sh), the procedural room seen through its open
# front and the animated scene file's first frame, every architecture at the common
# configuration (16 units, the cached preset; the ray pipe at the seed's final build) and at its
# seed's (the SVO RTU at `thesis`, the BIH core at `fixedpoint`; the ray pipe's is its default;
# the BVH and k-d cores have no seed preset). One compare at a time, one worker (-j1): the rows
# are heavy.
# Writes OUT/SCENE-common.json and OUT/SCENE-seed.json (and the difference images), then the
# table (OUT/table.md) and the plots (docs/images/study_*.png) with bench/comparison_study.py.
#   bench/comparison_study.sh [OUT] [WIDTH] [HEIGHT] [SCENE ...]
# Scenes: bunny00 armadillo ChineseDragon-10kv refined_elephant room default (the scene file).
# A set whose JSON file exists is not run again (delete it to re-run). SLOW_BIH: the scenes
# whose BIH rows run at a quarter of the size, for a quick look (default: none).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
rtusim=${RTUSIM:-$root/build/rtusim}
out=${1:-$root/build/comparison-study}
width=${2:-1280}
height=${3:-720}
shift $(($# < 3 ? $# : 3))
scenes=("$@")
((${#scenes[@]})) || scenes=(bunny00 armadillo ChineseDragon-10kv refined_elephant room default)
mkdir -p "$out"

# The scene's flags: a CGAL mesh, the room through its open front at depth 8 (its faces for the
# triangle architectures: voxel_faces.h builds them to depth 9 at most) or the scene file.
scene_flags() {
  case $1 in
    room) echo "--scene room --depth 8 --camera 0,0.3,-1.1 --look-at 0,-0.45,0.6" ;;
    default) echo "--scene-file $root/scenes/default.toml" ;;
    *) echo "--mesh $("$root/bench/cgal_meshes.sh" "$1")" ;;
  esac
}

# The BIH core's rows are the study's longest (on the room about 5 minutes a row: 486 triangle
# tests a ray); SLOW_BIH="room default" runs them at a quarter of the size in each direction, in
# the sets common-bih and seed-bih.
slow_bih=${SLOW_BIH-}

# compare SCENE SET WIDTH HEIGHT ARCHITECTURES: one compare into OUT/SCENE-SET.json.
run() {
  local scene=$1 set=$2 w=$3 h=$4 architectures=$5
  local json=$out/$scene-$set.json
  [[ -f $json ]] && return
  echo "== $scene, $set: $architectures at ${w}x$h" >&2
  local start
  start=$(date +%s)
  "$rtusim" compare "${flags[@]}" --width "$w" --height "$h" -j 1 \
    --architectures "$architectures" --images "$out/$scene-$set" --json "$json.part" \
    --csv "$out/$scene-$set.csv"
  mv "$json.part" "$json"
  echo "== $scene, $set: $(($(date +%s) - start)) s" >&2
}

for scene in "${scenes[@]}"; do
  read -r -a flags <<<"$(scene_flags "$scene")"
  if [[ " $slow_bih " == *" $scene "* ]]; then
    run "$scene" common "$width" "$height" svo,bvh,kd,raypipe
    run "$scene" seed "$width" "$height" svo=thesis
    run "$scene" common-bih $((width / 4)) $((height / 4)) bih
    run "$scene" seed-bih $((width / 4)) $((height / 4)) bih=fixedpoint
  else
    run "$scene" common "$width" "$height" svo,bvh,bih,kd,raypipe
    run "$scene" seed "$width" "$height" svo=thesis,bih=fixedpoint
  fi
done
/usr/bin/python3 "$root/bench/comparison_study.py" "$out" "$root/docs/images" >"$out/table.md"
echo "wrote $out/table.md and docs/images/study_*.png" >&2
