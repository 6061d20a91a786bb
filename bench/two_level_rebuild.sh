#!/usr/bin/env bash
# The two-level BVH's per-frame top-level rebuild (docs/triangles.md, "The two-level BVH in the
# core"; seed 003 §3.2.1): scene files of N instances of the spider (assimp-testmodels), in a grid,
# each moving and turning, run by `animate --core bvh` on the golden model over a few small frames.
# Prints one markdown row per N: instances, the top level's nodes and SAH, its mean and largest
# build time per frame (wall clock), and the frames' mean cycles and instances entered per ray.
# Usage: bench/two_level_rebuild.sh [rtusim] [frames] [counts...]
set -euo pipefail

rtusim=${1:-$(dirname "$0")/../build/rtusim}
frames=${2:-8}
shift $(($# > 2 ? 2 : $#))
counts=("$@")
((${#counts[@]})) || counts=(4 16 64 256 1024 4096)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

scene() {  # N instances on a grid in x, z, each sliding along x and turning about y
  local n=$1
  python3 - "$n" <<'PY'
import math, sys
n = int(sys.argv[1])
side = math.ceil(math.sqrt(n))
print('width = 64\nheight = 36\nframes = 8\nframe_rate = 8\n')
print('[models.spider]\nmesh = "/usr/share/assimp/models/OBJ/spider.obj"\ndepth = 8\n')
for i in range(n):
    x, z = (i % side - side / 2) * 2.2, (i // side) * 2.2
    print('[[instances]]\nmodel = "spider"')
    print(f'keys = [{{ time = 0, translation = [{x:.3f}, 0, {z:.3f}], rotation_deg = [0, {(37 * i) % 360}, 0], scale = 0.8 }},'
          f' {{ time = 1, translation = [{x + 1.0:.3f}, 0.2, {z:.3f}], rotation_deg = [0, {(37 * i + 90) % 360}, 0] }}]')
print(f'\n[camera]\nkeys = [{{ time = 0, position = [0, {side * 1.2:.2f}, {-side * 1.5:.2f}], look_at = [0, 0, {side:.2f}] }}]')
PY
}

echo "| instances | top nodes | top SAH (unit) | build mean [µs] | build max [µs] | cycles per frame | instances entered per ray |"
echo "|---|---|---|---|---|---|---|"
for n in "${counts[@]}"; do
  scene "$n" >"$work/s$n.toml"
  "$rtusim" animate --core bvh --scene-file "$work/s$n.toml" --frames "$frames" \
    --out-dir "$work/a$n" --model golden --cores 16 >"$work/a$n.txt"
  python3 - "$work/a$n/frames.csv" "$n" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
build = [float(r["top_build_s"]) * 1e6 for r in rows]
mean = lambda key: sum(float(r[key]) for r in rows) / len(rows)
print(f"| {sys.argv[2]} | {rows[0]['top_nodes']} | {mean('top_sah'):.2f} | {sum(build) / len(build):.1f} | "
      f"{max(build):.1f} | {mean('cycles'):.0f} | {mean('instances_per_ray'):.2f} |")
PY
done
