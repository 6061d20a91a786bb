#!/usr/bin/env bash
# Seed 001's ray pipe explored (issue 29): `fps --architecture raypipe` (rows per resolution, the
# seed's levels by default, on the pipe's timed model), `sweep` over raypipe.* keys through the
# same workers (beside the RTU's rows), `render --stats` with the pipe's statistics, and `fidelity`: the timed model and
# the golden traversal against the per-cycle reference. Small frames (20x15 to 60x45) of a voxel
# sphere's faces, so that it runs in a few seconds. Usage: cli_raypipe_explore.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"
scene=(--scene sphere --depth 3 --index wide)

# render --stats: the timed frame's statistics, as the timing line says.
"$rtusim" render --preset trayracer "${scene[@]}" --level 0 --stats render.json >render.txt
cycles=$(sed -n 's/^timing *\([0-9]*\) cycles at 50 MHz: .*/\1/p' render.txt)
[[ -n $cycles ]] || fail "no timing line: $(cat render.txt)"
grep -q "^wrote       render.json" render.txt || fail "no wrote line: $(cat render.txt)"
python3 - render.json "$cycles" <<'PY' || fail "render --stats"
import json, sys
run = json.load(open(sys.argv[1]))
s = run["statistics"]
assert run["config"]["architecture"] == "raypipe" and run["config"]["raypipe.level"] == 0
assert s["rays"] == 300 and s["total_cycles"] == int(sys.argv[2]), s
assert s["hits"] + s["misses"] + s["box_misses"] == 300 and s["hits"] > 0, s
assert abs(s["fps"] - 50e6 / s["total_cycles"]) < 1e-6 * s["fps"], s
assert s["simulation"]["model"] == "raypipe" and s["clock_mhz"] == 50, s
units = {u["unit"]: u for u in s["units"]}
# Every pixel passes the PRG, SINT, the shader's return and the writer once.
for unit in ("prg", "sint", "shader_return", "pixel_writer"):
    assert units[unit]["busy"] == 300, units[unit]
assert units["prg"]["interval"] == 3 and units["trav"]["interval"] == 1
for u in s["units"]:
    assert abs(u["utilisation"] - u["busy"] * u["interval"] / s["total_cycles"]) < 1e-12, u
top = max(s["units"], key=lambda u: u["utilisation"])
# The VGA window bounds the frame when no unit is saturated and the writer held a pixel (took it or
# waited for the reader) in 0.8 of the cycles.
writer = units["pixel_writer"]
held = (writer["busy"] + s["writer"]["waits"]) / s["total_cycles"]
window = top["utilisation"] < 0.8 and s["writer"]["waits"] > 0 and held >= 0.8
assert s["limit_utilisation"] == (held if window else top["utilisation"])
assert s["limit"] == ("vga_window" if window else top["unit"] if top["utilisation"] >= 0.8
                      else "none"), s["limit"]
fifos = {f["fifo"]: f for f in s["fifos"]}
assert all(f["peak"] <= f["depth"] for f in s["fifos"]), s["fifos"]
assert 0 < s["ray_ids"]["most_held"] <= s["ray_ids"]["available"] == 512, s["ray_ids"]
assert s["writer"]["last_write_cycle"] >= s["total_cycles"] - 1, s["writer"]
PY
expect_error "golden model is untimed" "$rtusim" render --preset trayracer --model golden \
  "${scene[@]}" --level 0 --stats g.json

# fps: one row per resolution, none per core; a level's size runs at that level, another size as
# docs/raypipe.md's other sizes. The 20x15 row is render's frame above.
"$rtusim" fps --preset trayracer "${scene[@]}" --resolutions 20x15,40x30,60x45 --csv fps.csv \
  -j 2 >fps.txt 2>fps.err
grep -q "ray pipe (seed 001): short stack 4, 512 ray ids, 50 MHz, answered by the ray pipe's timed model" \
  fps.txt || fail "fps heading: $(cat fps.txt)"
grep -q "^20x15 *- *300 *$cycles " fps.txt || fail "fps 20x15 row: $(cat fps.txt)"
python3 - fps.csv fps.jsonl "$cycles" <<'PY' || fail "fps CSV"
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert [(r["width"], r["height"], r["cores"]) for r in rows] == \
       [("20", "15", ""), ("40", "30", ""), ("60", "45", "")], rows
assert [int(r["rays"]) for r in rows] == [300, 1200, 2700]
assert int(rows[0]["total_cycles"]) == int(sys.argv[3])
for r in rows:
    assert r["answered_by"] == "raypipe" and r["error"] == "" and r["limit"] != "", r
    assert abs(float(r["cycles_per_ray"]) - int(r["total_cycles"]) / int(r["rays"])) < 1e-6, r
    assert r["util_cores"] == "" and r["l1_hit_rate"] == "", r  # the RTU's resources: empty
lines = [json.loads(line) for line in open(sys.argv[2])]
assert [l["config"]["raypipe.level"] for l in lines] == [0, 1, -1]
assert all(l["status"] == "ok" for l in lines)
PY
expect_error "the ray pipe has no cores" "$rtusim" fps --preset trayracer "${scene[@]}" --cores 1,2
expect_error "rows run its timed model" "$rtusim" fps --preset trayracer --model golden \
  "${scene[@]}" --resolutions 20x15

# sweep: raypipe.* keys through the same workers, each row carrying its configuration. The ray ids
# change timing only: the same hits; with 4 in flight the frame takes longer.
"$rtusim" sweep --preset trayracer "${scene[@]}" --level 0 --grid raypipe.rays_in_flight=4,512 \
  --grid raypipe.short_stack_depth=1,4 --out sweep.csv -j 2 >sweep.txt 2>sweep.err
grep -q "sweep: 4 rows done, 0 failed" sweep.txt || fail "sweep: $(cat sweep.txt)"
python3 - sweep.csv "$cycles" <<'PY' || fail "sweep CSV"
import csv, sys
rows = {(r["raypipe.rays_in_flight"], r["raypipe.short_stack_depth"]): r
        for r in csv.DictReader(open(sys.argv[1]))}
assert sorted(rows) == [("4", "1"), ("4", "4"), ("512", "1"), ("512", "4")], sorted(rows)
assert all(r["status"] == "ok" and r["rays"] == "300" for r in rows.values())
assert int(rows[("512", "4")]["total_cycles"]) == int(sys.argv[2])
for depth in ("1", "4"):
    assert int(rows[("4", depth)]["total_cycles"]) > int(rows[("512", depth)]["total_cycles"])
PY
# The pipe and the RTU in one sweep: each row answered by its own model.
"$rtusim" sweep --scene sphere --depth 3 --width 40 --height 30 --grid architecture=rtu,raypipe \
  --out mixed.csv -j 2 >mixed.txt 2>mixed.err
python3 - mixed.csv <<'PY' || fail "mixed sweep"
import csv, sys
rows = {r["architecture"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert rows["rtu"]["answered_by"] == "systemc" and rows["raypipe"]["answered_by"] == "raypipe"
assert all(r["status"] == "ok" and r["rays"] == "1200" for r in rows.values()), rows
PY
# The designed set-associative caches in front of DRAM: rows of their own, the same results; small
# caches take more cycles and read lines from DRAM. A size the caches cannot take is an invalid row,
# refused before it runs.
"$rtusim" sweep --preset trayracer "${scene[@]}" --level 0 \
  --grid raypipe.cache=block_ram,set_associative --set raypipe.cache_lines.tcache=4 \
  --set raypipe.cache_lines.icache=4 --out caches.csv -j 1 >/dev/null || fail "cache rows"
python3 - caches.jsonl "$cycles" <<'PY' || fail "cache rows"
import json, sys
rows = {r["config"]["raypipe.cache"]: r for r in map(json.loads, open(sys.argv[1]))}
built, cached = rows["block_ram"]["statistics"], rows["set_associative"]["statistics"]
assert built["total_cycles"] == int(sys.argv[2]) and built["caches"] == [], built
assert cached["total_cycles"] > built["total_cycles"], cached["total_cycles"]
for key in ("hits", "misses", "box_misses"):
    assert cached[key] == built[key], key
names = [c["cache"] for c in cached["caches"]]
assert names == ["tcache", "lcache", "icache"], names
assert sum(c["fills"] for c in cached["caches"]) == cached["dram"]["reads"] > 0, cached["dram"]
assert cached["dram"]["bytes"] >= 32 * cached["dram"]["reads"], cached["dram"]
PY
expect_error "1 rows failed, the first: raypipe.cache_lines.tcache" "$rtusim" sweep \
  --preset trayracer "${scene[@]}" --level 0 --set raypipe.cache=set_associative \
  --grid raypipe.cache_lines.tcache=4,3 --out lines.csv -j 1
grep -q '"status":"invalid"' lines.jsonl || fail "3 lines a way is not an invalid row"
# Two traversal units (raypipe_2trav.sv): a row of its own, the same rays.
"$rtusim" sweep --preset trayracer "${scene[@]}" --level 0 --grid raypipe.traversal_units=1,2 \
  --out units.csv -j 1 >/dev/null || fail "traversal_units=1,2"
python3 - units.csv <<'PY' || fail "traversal_units rows"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert [r["raypipe.traversal_units"] for r in rows] == ["1", "2"], rows
assert all(r["status"] == "ok" and r["rays"] == "300" for r in rows), rows
PY

# fidelity: the timed model and golden against the per-cycle reference, all equal.
"$rtusim" fidelity --preset trayracer "${scene[@]}" --level 0 --csv fidelity.csv >fidelity.txt
python3 - fidelity.csv "$cycles" <<'PY' || fail "fidelity CSV"
import csv, sys
rows = {r["mode"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert list(rows) == ["reference", "raypipe", "golden"], list(rows)
for mode in ("reference", "raypipe"):
    r = rows[mode]
    assert int(float(r["total_cycles"])) == int(sys.argv[2]), r
    assert float(r["total_cycles_error"]) == 0 and float(r["per_ray_error_mean"]) == 0, r
    assert r["results_equal_golden"] == "yes", r
assert rows["golden"]["total_cycles"] == "" and rows["golden"]["results_equal_golden"] == "yes"
PY
# ... and with small set-associative caches and two traversal units: the timed model equals the
# reference in every ray.
"$rtusim" fidelity --preset trayracer "${scene[@]}" --level 0 --set raypipe.cache=set_associative \
  --set raypipe.cache_lines.tcache=4 --set raypipe.traversal_units=2 --csv fidelity_caches.csv \
  >/dev/null || fail "fidelity caches"
python3 - fidelity_caches.csv "$cycles" <<'PY' || fail "fidelity CSV with the caches"
import csv, sys
rows = {r["mode"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert int(float(rows["reference"]["total_cycles"])) > int(sys.argv[2]), rows["reference"]
r = rows["raypipe"]
assert float(r["total_cycles_error"]) == 0 and float(r["per_ray_error_mean"]) == 0, r
assert r["results_equal_golden"] == "yes", r
PY
expect_error "no loosely-timed or sampled mode" "$rtusim" fidelity --preset trayracer \
  "${scene[@]}" --level 0 --quanta 100
echo "cli_raypipe_explore: OK"
