#!/usr/bin/env bash
# `rtusim render --core kd` end to end (issue 28): a voxel scene's faces built into seed 001's k-d
# tree (PBRT v1's SAH, the Tray Racer's parameters) and traced as world-space ray records on the
# golden, loosely-timed and cycle-accurate models. The three models find the same hits at the same
# cost; the statistics carry the k-d counters, consistent with the report; the short stack and
# the shared units' cycles reach the core (a one-entry stack restarts more and finds the same
# hits); a sweep over `core` counts the k-d core's own setting in the k-d rows only.
# Usage: cli_kd_render.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"
frame=(--scene sphere --depth 5 --width 48 --height 32)

hits() { sed -n 's/^hits *\([0-9]*\) .*/\1/p' "$1"; }
cost() { sed -n 's/^cost *mean \([0-9.]*\),.*/\1/p' "$1"; }
restarts() { sed -n 's/^kd .*triangle tests, \([0-9.]*\) restarts.*/\1/p' "$1"; }

"$rtusim" render --core kd "${frame[@]}" --model golden --image golden.png >golden.txt
"$rtusim" render --core kd "${frame[@]}" --model lt --cores 4 >lt.txt
"$rtusim" render --core kd "${frame[@]}" --model ca --cores 4 --memory cached --stats ca.json \
  --image ca.png --depth-image depth.png --cost-image cost.png >ca.txt
golden=$(hits golden.txt)
# The default edge order (flat, accel.kd_edge_order) lists every voxel face, as PBRT's does, so the
# k-d core finds the BVH's hits; R1's lists no face flat on a split plane at the split, which on a
# voxel scene is most faces (docs/triangles.md, "The k-d core"): fewer hits.
"$rtusim" render --core bvh "${frame[@]}" --model golden >bvh.txt
[[ -n $golden && $golden == "$(hits bvh.txt)" ]] ||
  fail "k-d core $golden hits, BVH $(hits bvh.txt): $(cat golden.txt)"
"$rtusim" render --core kd "${frame[@]}" --model golden --kd-edge-order r1 >r1.txt
[[ $(hits r1.txt) -lt $((golden / 2)) ]] || fail "R1's order finds $(hits r1.txt) of $golden hits"
"$rtusim" render --core kd "${frame[@]}" --model golden --kd-edge-order pbrt >pbrt.txt
[[ $(hits pbrt.txt) == "$golden" ]] || fail "PBRT's order finds $(hits pbrt.txt) of $golden hits"
grep -q "k-d tree (PBRT v1 SAH, R1's edge order, wide scene file)" r1.txt ||
  fail "R1's scene line: $(cat r1.txt)"
# A voxel scene filling the cube [-1, 1]^3: its outer faces lie at distance 1 from the origin, where
# R1's unit-triangle matrices (accel.kd_matrix r1, the seed's) are singular and never hit, so the
# k-d core sees the sponge's inside (docs/triangles.md, "Faces on the scene box"); with the normal
# column (the default) it agrees with the float64 reference on every pixel, as the BVH does.
menger=(--scene menger --depth 2 --width 48 --height 32 --architectures bvh,kd -j 1)
"$rtusim" compare "${menger[@]}" --kd-matrix r1 --json as_built.json >as_built.txt 2>&1 ||
  fail "compare menger --kd-matrix r1: $(cat as_built.txt)"
"$rtusim" compare "${menger[@]}" --json normal.json >normal.txt 2>&1 ||
  fail "compare menger: $(cat normal.txt)"
python3 - as_built.json normal.json <<'PY' || fail "menger's faces: $(cat as_built.txt normal.txt)"
import json, sys
as_built, normal = ({r["architecture"]: r["agreement"] for r in json.load(open(p))["rows"]}
                    for p in sys.argv[1:])
assert as_built["bvh"]["both_hit"] > 500 and as_built["bvh"]["hit_miss_differ"] == 0, as_built
assert as_built["kd"]["missed_hits"] > 100, as_built
for key in ("both_hit", "hit_miss_differ", "other_object"):
    assert normal["kd"][key] == normal["bvh"][key] == as_built["bvh"][key] * (key == "both_hit"), (
        key, normal)
kd = [r for r in json.load(open(sys.argv[1]))["rows"] if r["architecture"] == "kd"][0]
assert kd["structure"].startswith("k-d tree (PBRT v1 SAH, R1's matrices, wide"), kd["structure"]
PY
[[ $(hits lt.txt) == "$golden" ]] || fail "lt finds $(hits lt.txt) hits, golden $golden"
[[ $(hits ca.txt) == "$golden" ]] || fail "ca finds $(hits ca.txt) hits, golden $golden"
[[ $(cost lt.txt) == "$(cost golden.txt)" ]] || fail "lt cost $(cost lt.txt), golden $(cost golden.txt)"
grep -q "^scene       sphere (depth 5, voxel faces): k-d tree (PBRT v1 SAH, wide scene file), 6288 triangles" \
  golden.txt || fail "scene line: $(cat golden.txt)"
grep -q "^model       golden, kd core, 4-entry short stack, triangle unit 1 cycles" golden.txt ||
  fail "core line: $(cat golden.txt)"
for image in golden.png ca.png depth.png cost.png; do
  [[ -s $image ]] || fail "$image not written"
done
cmp -s golden.png ca.png || fail "golden and ca shade the frame differently"

python3 - ca.json ca.txt <<'PY' || fail "statistics JSON"
import json, re, sys
run = json.load(open(sys.argv[1]))
stats = run["statistics"]
assert run["config"]["core"] == "kd" and run["config"]["core.short_stack"] == 4
jobs = sum(core["jobs"] for core in stats["cores"])
assert jobs == 48 * 32, jobs
nodes, tests = stats["kd_nodes_visited"], stats["kd_triangle_tests"]
assert nodes > 0 and tests > 0, stats
# 16 bytes an access: a node is one, a triangle four (LIST, UTTM0-2)
assert stats["kd_bytes_fetched"] == 16 * (nodes + 4 * tests), stats
# a run writes its own kind's counters only
assert not [k for k in stats if k.startswith(("bvh_", "bih_"))], stats
report = open(sys.argv[2]).read()
line = re.search(r"^kd +([0-9.]+) nodes, ([0-9.]+) triangle tests", report, re.M)
assert abs(float(line.group(1)) - nodes / jobs) < 0.01, (line.group(0), nodes)
assert abs(float(line.group(2)) - tests / jobs) < 0.01, (line.group(0), tests)
PY

# A one-entry short stack: the same hits, more restarts; slower units cost more.
"$rtusim" render --core kd "${frame[@]}" --model golden --short-stack 1 >shallow.txt
[[ $(hits shallow.txt) == "$golden" ]] || fail "a 1-entry stack finds $(hits shallow.txt) hits"
python3 -c "import sys; sys.exit(not $(restarts shallow.txt) > $(restarts golden.txt))" ||
  fail "restarts: 1 entry $(restarts shallow.txt), 4 entries $(restarts golden.txt)"
"$rtusim" render --core kd "${frame[@]}" --model golden --triangle-latency 9 --box-latency 2 >slow.txt
[[ $(hits slow.txt) == "$golden" ]] || fail "slower units find $(hits slow.txt) hits"
python3 -c "import sys; sys.exit(not $(cost slow.txt) > $(cost golden.txt))" ||
  fail "slower units cost $(cost slow.txt), the defaults $(cost golden.txt)"

# A sweep over two triangle kinds: the short stack counts in the k-d rows only.
"$rtusim" sweep "${frame[@]}" --grid core=bvh,kd --grid core.short_stack=1,4 -j 1 \
  --out kinds.csv >kinds.txt 2>kinds.err
grep -q "core.short_stack (sweep) has no effect in 2 of 4 configurations" kinds.err ||
  fail "the short stack in BVH rows: $(cat kinds.err)"
python3 - kinds.csv <<'PY' || fail "sweep rows: $(cat kinds.csv)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
kd = {r["core.short_stack"]: r for r in rows if r["core"] == "kd"}
bvh = [r for r in rows if r["core"] == "bvh"]
assert len(kd) == 2 and len(bvh) == 2, rows
assert int(kd["1"]["kd_restarts"]) > int(kd["4"]["kd_restarts"]), rows
# another kind's columns are empty in a row
assert kd["4"]["bvh_nodes_visited"] == "" and int(kd["4"]["kd_nodes_visited"]) > 0, rows
assert all(r["kd_nodes_visited"] == "" for r in bvh), rows
assert bvh[0]["total_cycles"] == bvh[1]["total_cycles"], rows
PY
echo "kd render: ok"
