#!/usr/bin/env bash
# `rtusim render --core bih` end to end (issue 28): a voxel scene's faces quantised to seed 004's
# grid, built into a BIH and traced as world-space ray records on the golden, loosely-timed and
# cycle-accurate models. The three models find the same hits, and the same hits as the BVH core on
# the same scene and camera (the voxel faces lie on the grid, so the quantisation moves none); the
# statistics carry the BIH counters, consistent with the report; the number formats and the unit's
# latency reach the core; the seed's 10-bit indices refuse a larger tree naming the wide index; a
# sweep over `core` counts the BIH's own settings in the BIH rows.
# Usage: cli_bih_render.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"
frame=(--scene sphere --depth 5 --width 48 --height 32)
bih=(--core bih --index wide)

hits() { sed -n 's/^hits *\([0-9]*\) .*/\1/p' "$1"; }
cost() { sed -n 's/^cost *mean \([0-9.]*\),.*/\1/p' "$1"; }

"$rtusim" render "${bih[@]}" "${frame[@]}" --model golden --image golden.png >golden.txt
"$rtusim" render "${bih[@]}" "${frame[@]}" --model lt --cores 4 >lt.txt
"$rtusim" render "${bih[@]}" "${frame[@]}" --model ca --cores 4 --memory cached --stats ca.json \
  --image ca.png --depth-image depth.png --cost-image cost.png >ca.txt
"$rtusim" render --core bvh "${frame[@]}" --model golden --image bvh.png >bvh.txt
golden=$(hits golden.txt)
[[ -n $golden && $golden -gt 100 ]] || fail "golden report: $(cat golden.txt)"
[[ $(hits lt.txt) == "$golden" ]] || fail "lt finds $(hits lt.txt) hits, golden $golden"
[[ $(hits ca.txt) == "$golden" ]] || fail "ca finds $(hits ca.txt) hits, golden $golden"
[[ $(hits bvh.txt) == "$golden" ]] || fail "the BVH finds $(hits bvh.txt) hits, the BIH $golden"
[[ $(cost lt.txt) == "$(cost golden.txt)" ]] || fail "lt cost $(cost lt.txt), golden $(cost golden.txt)"
grep -q "^scene       sphere (depth 5, voxel faces): BIH (c99 formats, wide indices), 6288 triangles" \
  golden.txt || fail "scene line: $(cat golden.txt)"
grep -q "^model       golden, bih core, c99 fixed-point formats, triangle unit 41 cycles" golden.txt ||
  fail "core line: $(cat golden.txt)"
for image in golden.png ca.png depth.png cost.png; do
  [[ -s $image ]] || fail "$image not written"
done
cmp -s golden.png ca.png || fail "golden and ca shade the frame differently"

python3 - ca.json ca.txt <<'PY' || fail "statistics JSON"
import json, re, sys
run = json.load(open(sys.argv[1]))
stats = run["statistics"]
assert run["config"]["core"] == "bih" and run["config"]["accel.index"] == "wide"
jobs = sum(core["jobs"] for core in stats["cores"])
assert jobs == 48 * 32, jobs
nodes, tests = stats["bih_nodes_visited"], stats["bih_triangle_tests"]
assert nodes > 0 and tests > 0 and stats["bih_stack_overflows"] == 0, stats
# 16 bytes an access; a node triple or a triangle record is at least one
assert stats["bih_bytes_fetched"] >= 16 * (nodes + tests), stats
# its own kind's counters only
assert not [key for key in stats if key.startswith("bvh_") or key == "stack_overflows"], stats
report = open(sys.argv[2]).read()
line = re.search(r"^bih +([0-9.]+) nodes, ([0-9.]+) triangle tests", report, re.M)
assert abs(float(line.group(1)) - nodes / jobs) < 0.01, (line.group(0), nodes)
assert abs(float(line.group(2)) - tests / jobs) < 0.01, (line.group(0), tests)
PY

# The VHDL formats and a shorter unit reach the core; a one-cycle unit costs less.
"$rtusim" render "${bih[@]}" "${frame[@]}" --model golden --bih-format vhdl >vhdl.txt
grep -q "BIH (vhdl formats, wide indices)" vhdl.txt || fail "vhdl formats: $(cat vhdl.txt)"
"$rtusim" render "${bih[@]}" "${frame[@]}" --model golden --bih-triangle-latency 1 >fast.txt
python3 -c "import sys; sys.exit(not $(cost fast.txt) < $(cost golden.txt))" ||
  fail "a 1-cycle unit costs $(cost fast.txt), the 41-cycle unit $(cost golden.txt)"

# Seed 004's hardware as a preset: one core at 233 MHz; the unit's fill rate is its tests (one
# cycle each) over the rays' cycles, as the report's own per-ray figures give it.
"$rtusim" render --preset fixedpoint "${frame[@]}" >preset.txt
grep -q "^model       ca, bih core, vhdl fixed-point formats, triangle unit 41 cycles" preset.txt ||
  fail "the fixedpoint preset's core: $(cat preset.txt)"
grep -q "at 233.00 MHz" preset.txt || fail "the fixedpoint preset's clock: $(cat preset.txt)"
grep -q "core time (1 cores)" preset.txt || fail "the fixedpoint preset's one core: $(cat preset.txt)"
python3 - preset.txt <<'PY' || fail "unit fill: $(cat preset.txt)"
import re, sys
report = open(sys.argv[1]).read()
tests = float(re.search(r"^bih +[0-9.]+ nodes, ([0-9.]+) triangle tests", report, re.M).group(1))
cost = float(re.search(r"^cost +mean ([0-9.]+),", report, re.M).group(1))
fill = float(re.search(r"^unit fill +([0-9.]+) %", report, re.M).group(1))
assert 0 < fill < 100 and abs(fill - 100 * tests / cost) < 0.1, (fill, tests, cost)
PY

# The seed's 10-bit node indices hold 1024 nodes: the frame's tree is refused, naming the way out.
expect_error "3951 nodes, more than 1024 (10-bit node indices; the wide index (accel.index = wide, --index wide) has 29)" \
  "$rtusim" render --core bih "${frame[@]}" --model golden

# A sweep over both triangle kinds: the BIH's settings count in its rows, not the BVH's.
"$rtusim" sweep "${frame[@]}" --index wide --grid core=bvh,bih --grid bih.triangle.latency=1,41 \
  -j 1 --out kinds.csv >kinds.txt 2>kinds.err
grep -q "accel.index (command line) has no effect in 2 of 4 configurations" kinds.err ||
  fail "the wide index in a sweep over core: $(cat kinds.err)"
grep -q "bih.triangle.latency (sweep) has no effect in 2 of 4 configurations" kinds.err ||
  fail "the BIH's latency in BVH rows: $(cat kinds.err)"
python3 - kinds.csv <<'PY' || fail "sweep rows: $(cat kinds.csv)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
bih = {r["bih.triangle.latency"]: r for r in rows if r["core"] == "bih"}
bvh = [r for r in rows if r["core"] == "bvh"]
assert len(bih) == 2 and len(bvh) == 2, rows
assert int(bih["1"]["bih_nodes_visited"]) > 0 and bih["1"]["bvh_nodes_visited"] == "", rows
assert int(bih["1"]["total_cycles"]) < int(bih["41"]["total_cycles"]), rows
assert bvh[0]["total_cycles"] == bvh[1]["total_cycles"], rows
PY
# Faces on the scene box (a voxel scene's outer faces): a ray clipped onto the box must still hit
# them (the grid's margin, docs/triangles.md "Faces on the scene box and flat triangles").
"$rtusim" compare --scene menger --depth 2 --width 48 --height 32 --architectures bvh,bih -j 1 \
  --json box_faces.json >box_faces.txt 2>&1 || fail "compare menger: $(cat box_faces.txt)"
python3 - box_faces.json <<'PY' || fail "menger's faces on the BIH: $(cat box_faces.txt)"
import json, sys
rows = {r["architecture"]: r["agreement"] for r in json.load(open(sys.argv[1]))["rows"]}
assert rows["bvh"]["both_hit"] > 500, rows
for key in ("both_hit", "hit_miss_differ", "other_object"):
    assert rows["bih"][key] == rows["bvh"][key], (key, rows)
assert rows["bih"]["other_object"] == 0, rows
PY
echo "bih render: ok"
