#!/usr/bin/env bash
# `rtusim render --core bvh` end to end (issue 28): a voxel scene's faces and a real mesh built
# into a BVH and traced as ray records on the golden, loosely-timed and cycle-accurate models.
# The three models find the same hits, and the SVO render of the same scene with the same camera
# nearly the same (the faces are the voxels' surface: only rays grazing an edge may differ); the
# cycle-accurate model's statistics carry the BVH counters, consistent with the report; the images
# are written; the BVH settings reach the core and have no effect on another.
# Usage: cli_bvh_render.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"
frame=(--scene sphere --depth 5 --width 48 --height 32)

hits() { sed -n 's/^hits *\([0-9]*\) .*/\1/p' "$1"; }

"$rtusim" render --core bvh "${frame[@]}" --model golden --image golden.png >golden.txt
"$rtusim" render --core bvh "${frame[@]}" --model lt --cores 4 >lt.txt
"$rtusim" render --core bvh "${frame[@]}" --model ca --cores 4 --memory cached --stats ca.json \
  --image ca.png --depth-image depth.png --cost-image cost.png >ca.txt
"$rtusim" render "${frame[@]}" --model golden >svo.txt
golden=$(hits golden.txt)
[[ -n $golden && $golden -gt 100 ]] || fail "golden report: $(cat golden.txt)"
[[ $(hits lt.txt) == "$golden" ]] || fail "lt finds $(hits lt.txt) hits, golden $golden"
[[ $(hits ca.txt) == "$golden" ]] || fail "ca finds $(hits ca.txt) hits, golden $golden"
grep -q "^scene       sphere (depth 5, voxel faces): binned BVH, .* triangles" golden.txt ||
  fail "scene line: $(cat golden.txt)"
svo=$(hits svo.txt)
[[ -n $svo ]] || fail "SVO report: $(cat svo.txt)"
python3 -c "import sys; sys.exit(abs($svo - $golden) > 0.02 * $svo)" ||
  fail "the BVH finds $golden hits, the SVO $svo on the same scene and camera"
for image in golden.png ca.png depth.png cost.png; do
  [[ -s $image ]] || fail "$image not written"
done
cmp -s golden.png ca.png || fail "golden and ca shade the frame differently"

python3 - ca.json ca.txt <<'PY' || fail "statistics JSON"
import json, re, sys
run = json.load(open(sys.argv[1]))
stats = run["statistics"]
cores = stats["cores"]
assert len(cores) == 4 and run["config"]["core"] == "bvh"
# The BVH counters are run totals (as the SVO's stack_overflows), the jobs per core.
total = {key: stats[key] for key in ["bvh_nodes_visited", "bvh_box_tests", "bvh_triangle_tests",
                                     "bvh_bytes_fetched", "bvh_stack_overflows"]}
total["jobs"] = sum(core["jobs"] for core in cores)
assert total["jobs"] == 48 * 32, total
assert total["bvh_box_tests"] >= total["bvh_nodes_visited"] > 0, total
assert total["bvh_triangle_tests"] > 0 and total["bvh_stack_overflows"] == 0, total
# Its own kind's counters only: none of the SVO's or the BIH's.
assert not [key for key in stats if key in ("stack_overflows", "t_overflows")
            or key.startswith("bih_")], list(stats)
# 16 bytes an access: two a node, four a triangle (its reference and its record).
assert total["bvh_bytes_fetched"] == 32 * total["bvh_nodes_visited"] + 64 * total["bvh_triangle_tests"], total
report = open(sys.argv[2]).read()
nodes = float(re.search(r"^bvh +([0-9.]+) nodes", report, re.M).group(1))
assert abs(nodes - total["bvh_nodes_visited"] / total["jobs"]) < 0.01, (nodes, total)
PY

# The units' cycles are in every model's cost; golden and ca agree on it with ideal memory.
slow=(--box-latency 3 --triangle-latency 9 --triangle-interval 2)
"$rtusim" render --core bvh "${frame[@]}" --model golden "${slow[@]}" >slow_golden.txt
"$rtusim" render --core bvh "${frame[@]}" --model ca "${slow[@]}" >slow_ca.txt
cost() { sed -n 's/^cost *mean \([0-9.]*\),.*/\1/p' "$1"; }
[[ $(cost slow_ca.txt) == "$(cost slow_golden.txt)" ]] || fail "slow units: ca $(cost slow_ca.txt), golden $(cost slow_golden.txt)"
python3 -c "import sys; sys.exit(not $(cost slow_golden.txt) > $(cost golden.txt) + 3)" ||
  fail "slower units cost no more: $(cost slow_golden.txt) against $(cost golden.txt)"
"$rtusim" render --core bvh "${frame[@]}" --model golden --triangle-test moller-trumbore \
  >moller.txt
grep -q "moller-trumbore test" moller.txt || fail "the triangle test reaches the core"

# A real mesh, fitted into the SVO's cube as the voxelizer fits it: the same camera sees it where
# it sees the voxelized spider (measured at 320x200: 2523 hits against the voxels' 2998, which
# are thicker than the triangles by up to a voxel).
spider=(--mesh /usr/share/assimp/models/OBJ/spider.obj --width 64 --height 48 --model golden)
"$rtusim" render --core bvh "${spider[@]}" --drop-bad-triangles --builder langr \
  --image spider.png >spider.txt
"$rtusim" render "${spider[@]}" >spider_svo.txt
grep -q "^scene       spider.obj: langr BVH, 1312 triangles" spider.txt ||
  fail "mesh render: $(cat spider.txt)"
python3 -c "import sys; sys.exit(not 0.7 * $(hits spider_svo.txt) <= $(hits spider.txt) <= $(hits spider_svo.txt))" ||
  fail "the BVH's spider: $(hits spider.txt) hits, the voxelized spider's $(hits spider_svo.txt)"

expect_error "an .svo image holds no triangles" \
  "$rtusim" render --core bvh --svo "$here/data/missing.svo" --width 8 --height 8
"$rtusim" render "${frame[@]}" --model golden --box-latency 4 >/dev/null 2>warn.txt
grep -q "core.box.latency (command line) has no effect: the core kind is svo" warn.txt ||
  fail "a BVH setting on the SVO core: $(cat warn.txt)"
echo "bvh render: ok"
