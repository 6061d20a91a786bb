#!/usr/bin/env bash
# `rtusim build --accel bvh`, `validate` and `golden --accel-file` on the images: builds over a
# real mesh and a voxel scene's faces, the quality figures as JSON, results as CSV checked against
# the image's triangles, and clear errors with a non-zero exit for a mesh with bad triangles,
# impossible settings and a corrupt image.
# Usage: cli_triangle_builds.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"
spider=/usr/share/assimp/models/OBJ/spider.obj

# spider.obj has 56 zero-area triangles: refused, with the way on named, then dropped.
expect_error "56 degenerate (zero-area) triangles: triangle (924, 927, 930, 932, 936, ...); drop them with --drop-bad-triangles" \
  "$rtusim" build --accel bvh --mesh "$spider" --out s.bvh
[[ ! -e s.bvh ]] || fail "a refused build wrote its image"
"$rtusim" build --accel bvh --builder langr --mesh "$spider" --drop-bad-triangles --out s.bvh \
  --stats s.json >build.txt
grep -q "^spider.obj: 1312 triangles (56 degenerate or duplicate dropped)$" build.txt ||
  fail "build report: $(cat build.txt)"
grep -q "^langr BVH: .* nodes" build.txt || fail "build report names the builder"
python3 - s.json s.bvh <<'PY' || fail "statistics JSON"
import json, os, sys
stats = json.load(open(sys.argv[1]))
for key in ["triangles", "nodes", "leaves", "empty_leaves", "depth", "triangles_per_leaf_mean",
            "triangles_per_leaf_max", "sah", "sah_seed", "bytes", "build_seconds", "accel",
            "builder", "scene", "dropped_triangles"]:
    assert key in stats, key
assert stats["triangles"] == 1312 and stats["dropped_triangles"] == 56
ids = stats["dropped_triangle_ids"]  # the file's ids, as the refusal above named the first five
assert len(ids) == 56 and ids[:5] == [924, 927, 930, 932, 936] and ids == sorted(set(ids))
assert stats["accel"] == "bvh" and stats["builder"] == "langr"
assert stats["nodes"] == 2 * stats["leaves"] - 1          # a binary tree
assert stats["triangles_per_leaf_max"] <= 10              # langr's leaves
assert stats["bytes"] == os.path.getsize(sys.argv[2])
PY
"$rtusim" validate s.bvh | grep -q "^s.bvh: valid BVH image, .* nodes, 1312 triangles" ||
  fail "validate the BVH"

# The golden model on the BVH: ray records of a camera looking at the spider, results as CSV. Each
# hit is recomputed from the image's own triangle record in double: t along the record's
# direction and hit = (1-u-v) v0 + u v1 + v v2.
"$rtusim" jobs --width 24 --height 16 --camera 0,40,260 --look-at 0,0,0 --fov 30 --rays rays.bin \
  --model-address 0 >/dev/null
"$rtusim" golden --accel-file s.bvh --rays rays.bin --results-csv r.csv >golden.txt
grep -q "^rays        384$" golden.txt || fail "golden report: $(cat golden.txt)"
python3 - s.bvh rays.bin r.csv <<'PY' || fail "results CSV"
import csv, struct, sys
image = open(sys.argv[1], "rb").read()
words = struct.unpack("<%dI" % (len(image) // 4), image)
floats = struct.unpack("<%df" % (len(image) // 4), image)
triangles = words[8]  # header word 8: the triangles' base
raw = open(sys.argv[2], "rb").read()
rays = [struct.unpack("<I6fI", raw[32 * i:32 * i + 32]) for i in range(len(raw) // 32)]
rows = list(csv.DictReader(open(sys.argv[3])))
assert len(rows) == len(rays) and list(rows[0]) == ["id", "hit", "t", "primitive", "u", "v"]
hits = 0
for row, ray in zip(rows, rays):
    assert int(row["id"]) == ray[0]
    if row["hit"] == "0":
        assert row["t"] == row["primitive"] == row["u"] == row["v"] == ""
        continue
    hits += 1
    base = triangles + 12 * int(row["primitive"])
    v = [floats[base + 3 * k: base + 3 * k + 3] for k in range(3)]
    t, u, w = float(row["t"]), float(row["u"]), float(row["v"])
    assert u >= 0 and w >= 0 and u + w <= 1 + 1e-6, row
    for axis in range(3):
        on_ray = ray[1 + axis] + t * ray[4 + axis]
        on_triangle = (1 - u - w) * v[0][axis] + u * v[1][axis] + w * v[2][axis]
        assert abs(on_ray - on_triangle) <= 1e-3, (row, axis, on_ray, on_triangle)
assert hits > 30, hits
PY

# Seed 004's BIH on its integer grid: spider's list overflows the seed's 10-bit index (refused,
# naming the limit and the way on) and fits the wide one, with the seed's capacity as a warning.
expect_error "1312 list entries, more than 1024 (10-bit node indices; the wide index (accel.index = wide, --index wide) has 29)" \
  "$rtusim" build --accel bih --mesh "$spider" --drop-bad-triangles --out s.bih
"$rtusim" build --accel bih --index wide --mesh "$spider" --drop-bad-triangles --out s.bih \
  --stats b.json >bih.txt 2>bih_warnings.txt
grep -q "^BIH (c99 formats, wide indices): .* nodes" bih.txt || fail "BIH build report"
grep -q "more than the seed's 992" bih_warnings.txt || fail "BIH capacity warning"
python3 - b.json <<'PY' || fail "BIH statistics JSON"
import json, sys
stats = json.load(open(sys.argv[1]))
assert stats["accel"] == "bih" and "builder" not in stats
assert stats["list_entries"] == 1312 and stats["sah_seed"] is None
assert stats["depth"] <= 31  # the seed's 32-entry stack
PY
"$rtusim" validate s.bih | grep -q "^s.bih: valid BIH image, .* nodes, 1312 list entries" ||
  fail "validate the BIH"

# The golden model on the BIH, in the image's own space (its grid): the BVH's camera rays moved
# onto the grid (the spider's float32 box from the BVH's triangle records, scale (2^n - 1) / its
# longest side) hit the same triangles as on the BVH, at t scaled by the grid's scale, up to
# float32 origins on a 2^29 grid (a grid coordinate carries 24 bits: within 2^-20 of the grid's
# side) and the grid's rounding (rays near edges may differ: at most 5 %).
python3 "$here/bih_grid_rays.py" s.bvh s.bih rays.bin grid_rays.bin grid_scale.txt
python3 -c "
raw = open('grid_rays.bin', 'rb').read(); open('bad_rays.bin', 'wb').write(raw[:28] + bytes([7, 0, 0, 0]))"
"$rtusim" golden --accel-file s.bih --rays grid_rays.bin --results-csv rb.csv >golden_bih.txt \
  2>/dev/null
grep -q "^rays        384$" golden_bih.txt || fail "BIH golden report: $(cat golden_bih.txt)"
python3 - r.csv rb.csv grid_scale.txt <<'PY' || fail "BIH results CSV against the BVH's"
import csv, sys
bvh = list(csv.DictReader(open(sys.argv[1])))
bih = list(csv.DictReader(open(sys.argv[2])))
scale, n = open(sys.argv[3]).read().split()
scale, n = float(scale), int(n)
assert len(bvh) == len(bih) == 384
differ = 0
for a, b in zip(bvh, bih):
    assert a["id"] == b["id"]
    if a["hit"] != b["hit"] or a["primitive"] != b["primitive"]:
        differ += 1
        continue
    if a["hit"] == "1":
        assert abs(float(a["t"]) * scale - float(b["t"])) <= 2 ** (n - 20), (a, b)
        assert 0 <= float(b["u"]) and 0 <= float(b["v"]) and float(b["u"]) + float(b["v"]) <= 1, b
assert sum(r["hit"] == "1" for r in bih) > 30
print("BIH against BVH: %d of %d rays differ" % (differ, len(bvh)))
assert differ <= 0.05 * len(bvh), differ
PY
expect_error "names model address 7; an image file has no model headers: give 0" \
  "$rtusim" golden --accel-file s.bih --rays bad_rays.bin --results-csv x.csv

# Seed 001's k-d tree: the core's image, the Tray Racer's own file, and its capacities as warnings.
"$rtusim" build --accel kdtree --mesh "$spider" --drop-bad-triangles --out s.kd --stats k.json \
  --trayracer-scene s.scene >kd.txt 2>kd_warnings.txt
grep -q "^k-d tree (PBRT v1 SAH, seed scene file): .* nodes" kd.txt || fail "k-d build report"
grep -q "exceeds the Tray Racer's 4096" kd_warnings.txt || fail "k-d capacity warning"
[[ -s s.scene ]] || fail "the Tray Racer scene file"
python3 - k.json <<'PY' || fail "k-d statistics JSON"
import json, sys
stats = json.load(open(sys.argv[1]))
assert stats["accel"] == "kdtree" and stats["builder"] == "pbrt"
assert stats["triangles"] == 1312 and stats["list_entries"] >= stats["triangles"]
assert stats["sah_seed"] > stats["sah"]  # PBRT's intersection cost is 80
PY
"$rtusim" validate s.kd | grep -q "^s.kd: valid k-d image, .* nodes" || fail "validate the k-d image"
"$rtusim" golden --accel-file s.kd --rays rays.bin --results-csv kd.csv >golden_kd.txt \
  || fail "golden on the k-d image"
grep -q "^rays        384$" golden_kd.txt || fail "golden k-d report: $(cat golden_kd.txt)"
python3 - kd.csv r.csv <<'PY' || fail "golden on the k-d image against the BVH's"
import csv, sys
kd, bvh = ({r["id"]: r for r in csv.DictReader(open(p))} for p in sys.argv[1:3])
assert len(kd) == 384 and kd.keys() == bvh.keys()
# Float24 matrices against float32 vertices: a ray near an edge may go either way.
same = sum(kd[i]["hit"] == bvh[i]["hit"] and kd[i]["primitive"] == bvh[i]["primitive"] for i in kd)
assert same >= 0.95 * len(kd) and sum(r["hit"] == "1" for r in kd.values()) > 30, same
PY
expect_error "holds no bvh, bih or kd image" \
  "$rtusim" golden --accel-file s.scene --rays rays.bin --results-csv x.csv
expect_error "the Tray Racer's file holds a k-d tree" \
  "$rtusim" build --accel bvh --scene sphere --depth 3 --out x.bvh --trayracer-scene x.scene

# A voxel scene's faces: each of the sphere's exposed faces is two triangles.
"$rtusim" build --accel bvh --scene sphere --depth 4 --out sphere.bvh >sphere.txt
grep -q "^sphere (depth 4, voxel faces): [0-9]* triangles$" sphere.txt || fail "voxel faces"
"$rtusim" validate sphere.bvh | grep -q "valid BVH image" || fail "validate the sphere"

# A corrupt image: the root's left child index pointed past the nodes.
python3 - s.bvh bad.bvh <<'PY'
import struct, sys
words = list(struct.unpack("<%dI" % (len(open(sys.argv[1], "rb").read()) // 4),
                           open(sys.argv[1], "rb").read()))
words[words[4] + 6] = 0x7fffffff  # header word 4: the nodes' base; node word 6: left child
open(sys.argv[2], "wb").write(struct.pack("<%dI" % len(words), *words))
PY
expect_error "is not a sound BVH image" "$rtusim" validate bad.bvh
expect_error "an .svo image holds no triangles" "$rtusim" build --accel bvh --svo s.bvh --out x.bvh
expect_error "is not one of langr|binned|sweep|lbvh" \
  "$rtusim" build --accel bvh --builder nope --scene sphere --out x.bvh
expect_error "quality figures are written for --accel bvh, bih or kdtree" \
  "$rtusim" build --scene sphere --depth 3 --out x.svo --stats x.json
expect_error "beyond the deepest grid" "$rtusim" build --accel bvh --scene sphere --depth 10 --out x.bvh
expect_error "a triangle image traces ray records: give --rays" \
  "$rtusim" golden --accel-file s.bvh --jobs rays.bin --results-csv x.csv
expect_error "give one image: --svo or --accel-file" \
  "$rtusim" golden --accel-file s.bvh --svo sphere.bvh --rays rays.bin --results-csv x.csv
expect_error "is not a sound BVH image" "$rtusim" golden --accel-file bad.bvh --rays rays.bin \
  --results-csv x.csv

# Bad meshes are refused before any build, naming the file, for every structure: a vertex that is
# not a number (the OBJ reader refuses it by line; a NaN read from another format is refused by the
# mesh checks, tests/test_mesh_checks.cpp), a mesh without a triangle, a duplicate triangle (the
# later one named).
printf 'v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n' >nan.obj
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\n' >empty.obj
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\nf 3 1 2\n' >twice.obj
for accel in bvh bih kdtree; do
  expect_error "mesh 'nan.obj', line 3: 'nan' is not a decimal number" "$rtusim" build --accel $accel --mesh nan.obj --out x.img
  expect_error "empty.obj" "$rtusim" build --accel $accel --mesh empty.obj --out x.img
  expect_error "twice.obj'*: 1 duplicate triangles (the same vertices as an earlier one): triangle (2)" \
    "$rtusim" build --accel $accel --mesh twice.obj --out x.img
  [[ ! -e x.img ]] || fail "a refused $accel build wrote its image"
done
echo "triangle builds: all checks passed"
