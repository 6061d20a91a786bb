#!/usr/bin/env bash
# `rtusim build --accel bvh|bih` and `validate` on the images: builds over a real mesh and a voxel
# scene's faces, the quality figures as JSON, and clear errors with a non-zero exit for a mesh
# with bad triangles, impossible settings and a corrupt image.
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
assert stats["accel"] == "bvh" and stats["builder"] == "langr"
assert stats["nodes"] == 2 * stats["leaves"] - 1          # a binary tree
assert stats["triangles_per_leaf_max"] <= 10              # langr's leaves
assert stats["bytes"] == os.path.getsize(sys.argv[2])
PY
"$rtusim" validate s.bvh | grep -q "^s.bvh: valid BVH image, .* nodes, 1312 triangles" ||
  fail "validate the BVH"

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
expect_error "quality figures are written for --accel bvh or bih" \
  "$rtusim" build --scene sphere --depth 3 --out x.svo --stats x.json
expect_error "beyond the deepest grid" "$rtusim" build --accel bvh --scene sphere --depth 10 --out x.bvh
echo "triangle builds: all checks passed"
