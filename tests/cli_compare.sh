#!/usr/bin/env bash
# `rtusim compare` end to end (issue 30) on a voxel scene at 48x32: every architecture's row is the
# fps row of its configuration (statistics equal to `rtusim fps` run alone, the host's seconds
# aside); the SVO and the triangle architectures trace the same surface (each against the float64
# reference over the voxel faces: hit/miss disagreements counted and bounded); the outputs (CSV,
# JSON, HTML with its plots and difference images); bad inputs refused before any work; a scene
# file's frame, its SVO built once into the cache and read back by the next run.
# Usage: cli_compare.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"
frame=(--scene sphere --depth 5 --width 48 --height 32)

expect_error "no architecture 'octree' (svo, bvh, bih, kd, raypipe)" \
  "$rtusim" compare "${frame[@]}" --architectures svo,octree
expect_error "bvh is given twice" "$rtusim" compare "${frame[@]}" --architectures bvh,bvh
expect_error "depth 10: the triangle architectures trace the voxel scene's faces" \
  "$rtusim" compare --scene sphere --depth 10 --width 48 --height 32 --architectures svo,bvh
expect_error "depth" "$rtusim" compare --scene sphere --depth 0 --width 48 --height 32
expect_error "nopreset" "$rtusim" compare "${frame[@]}" --architectures bih=nopreset
[[ ! -e out.csv ]] || fail "a refused run wrote its CSV"

"$rtusim" compare "${frame[@]}" -j 2 --csv out.csv --json out.json --html out.html \
  --images diff >compare.txt 2>compare.err || fail "compare: $(cat compare.txt compare.err)"
for arch in svo bvh bih kd raypipe; do
  [[ -s diff/$arch.png ]] || fail "no difference image for $arch"
  grep -q "^$arch " compare.txt || fail "no line for $arch: $(cat compare.txt)"
done
"$rtusim" fps --preset cached --scene sphere --depth 5 --resolutions 48x32 --cores 16 \
  --csv svo.csv >/dev/null 2>&1
for core in bvh bih kd; do
  "$rtusim" fps --preset cached --core $core --index wide --scene sphere --depth 5 \
    --resolutions 48x32 --cores 16 --csv $core.csv >/dev/null 2>&1
done
"$rtusim" fps --architecture raypipe --index wide --scene sphere --depth 5 --resolutions 48x32 \
  --csv raypipe.csv >/dev/null 2>&1

python3 - out.json out.csv out.html <<'PY' || fail "compare's outputs"
import csv, json, sys
compared = json.load(open(sys.argv[1]))
rows = {r["architecture"]: r for r in compared["rows"]}
assert list(rows) == ["svo", "bvh", "bih", "kd", "raypipe"], list(rows)
assert all(r["status"] == "ok" for r in rows.values()), rows
# Each row is the single run of its architecture: fps with the same settings, alone.
def same(a, b):
    a, b = dict(a), dict(b)
    for s in (a, b):
        s.pop("simulation")
    return a == b
for arch in ("svo", "bvh", "bih", "kd", "raypipe"):
    alone = json.loads(open(arch + ".jsonl").readline())
    assert same(rows[arch]["row"]["statistics"], alone["statistics"]), arch
# The figures are the row's: frame cycles, rate, per-ray counts from the kind's own counters.
for arch, r in rows.items():
    s, f = r["row"]["statistics"], r["figures"]
    assert f["total_cycles"] == s["total_cycles"] and f["fps"] == s["fps"], arch
    assert r["image_bytes"] > 0 and r["build_seconds"] >= 0, arch
kd = rows["kd"]
assert abs(kd["figures"]["nodes_per_ray"] * 48 * 32 - kd["row"]["statistics"]["kd_nodes_visited"]) < 1e-6
assert rows["svo"]["figures"]["nodes_per_ray"] is None
assert rows["raypipe"]["figures"]["l1_hit_rate"] is None
# One surface: every architecture against the float64 reference over the voxel faces. The
# triangle architectures trace those faces (only rays along shared edges may differ); the SVO
# traces their voxels in Q16.16, so it may differ where a ray passes within its t error of a
# voxel's edge: a few pixels of 1,536 on the silhouette.
agreement = {a: r["agreement"] for a, r in rows.items()}
hits = agreement["bvh"]["both_hit"] + agreement["bvh"]["missed_hits"]
assert hits > 100, agreement
for arch, a in agreement.items():
    assert a["pixels"] == 48 * 32, (arch, a)
    bound = 8 if arch == "svo" else 2
    assert a["hit_miss_differ"] <= bound, (arch, a)
    # The BIH in seed 004's C99 formats (the default; the VHDL's find every nearest hit here) hits
    # a farther triangle on 12 pixels (docs/comparison.md, "Measured").
    if arch == "bih":
        assert a["other_object"] <= 16, a
        continue
    assert a["other_object"] <= bound, (arch, a)
    assert a["mean_depth_error"] < 1e-3, (arch, a)
print({a: (x["hit_miss_differ"], x["other_object"]) for a, x in agreement.items()})
table = list(csv.DictReader(open(sys.argv[2])))
assert [r["architecture"] for r in table] == list(rows), table
assert table[0]["total_cycles"] == str(rows["svo"]["figures"]["total_cycles"]), table[0]
# The resource estimate beside the raw figures: the fps row's, and the rate per resource. The
# SVO core has no multiplier (the thesis' 0 DSP), so no rate per DSP48E; the ray pipe's is its
# final build's (tests/test_resource_estimate.cpp counts it: 82 RAMB18, 62 DSP48E).
for arch, r in rows.items():
    resources, f = r["row"]["resources"], r["figures"]
    assert f["bram18k"] == resources["bram18k"] and f["dsp48e"] == resources["dsp48e"], arch
    if resources["bram18k"] > 0:
        assert abs(f["fps_per_bram18k"] - f["fps"] / resources["bram18k"]) < 1e-9 * f["fps"], arch
assert rows["svo"]["figures"]["dsp48e"] == 0 and rows["svo"]["figures"]["fps_per_dsp48e"] is None
assert rows["bvh"]["figures"]["multipliers"] > 0 and rows["bvh"]["figures"]["fps_per_dsp48e"] > 0
assert (rows["raypipe"]["figures"]["bram18k"], rows["raypipe"]["figures"]["dsp48e"]) == (82, 62)
csv_row = {r["architecture"]: r for r in table}
assert csv_row["svo"]["fps_per_dsp48e"] == "" and csv_row["raypipe"]["bram18k"] == "82", csv_row
report = open(sys.argv[3]).read()
assert report.count("data:image/png;base64") == 6 + 5, report.count("data:image/png;base64")
PY
# A scene file: its frame 0 flattened into one mesh for the triangle architectures and voxelized
# for the SVO at the footprint's depth, that SVO kept in the cache so a second run reads it back.
scene_file=(--scene-file "$here/../scenes/procedural.toml" --width 48 --height 27)
"$rtusim" compare "${scene_file[@]}" --architectures svo,bvh --cache-dir cache -j 1 \
  --json file.json >file.txt 2>file.err || fail "compare --scene-file: $(cat file.txt file.err)"
grep -q "SVO of frame 0 at depth [0-9]* built and cached in cache/" file.txt ||
  fail "the frame's SVO was not built into the cache: $(cat file.txt)"
"$rtusim" compare "${scene_file[@]}" --architectures svo --cache-dir cache -j 1 \
  --json again.json >again.txt 2>&1 || fail "compare --scene-file again: $(cat again.txt)"
grep -q "SVO of frame 0 at depth [0-9]* read from cache/" again.txt ||
  fail "the second run voxelized the frame again: $(cat again.txt)"
python3 - file.json again.json <<'PY' || fail "compare --scene-file's rows"
import json, sys
first, again = (json.load(open(p)) for p in sys.argv[1:])
rows = {r["architecture"]: r for r in first["rows"]}
assert all(r["status"] == "ok" for r in rows.values()), rows
assert (first["width"], first["height"]) == (48, 27), first
# The cached image is the one built: the same frame, cycle for cycle.
svo, cached = rows["svo"], again["rows"][0]
assert svo["row"]["statistics"]["total_cycles"] == cached["row"]["statistics"]["total_cycles"]
assert svo["image_bytes"] == cached["image_bytes"]
# The same surface: the BVH finds the reference's hits; the SVO's voxels stand at most a voxel
# proud of it, so only silhouette pixels differ.
bvh, voxels = rows["bvh"]["agreement"], svo["agreement"]
assert bvh["hit_miss_differ"] == 0 and bvh["both_hit"] > 500, bvh
assert voxels["hit_miss_differ"] <= 0.05 * bvh["both_hit"], voxels
PY
echo "compare: ok"
