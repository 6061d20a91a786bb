#!/usr/bin/env bash
# Issue 27 §4: `precision --triangles` on a tiny mesh (the tetrahedron, a closed mesh of 4
# triangles) in a few seconds: one table row and one CSV row per format, the sweep's rows and the
# stress rows, counts that add up, the float64 oracle's hits the same in every row; flags of the
# triangle study refused without --triangles, and a format out of range named before any tracing.
# Usage: triangle_precision.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
mesh=$here/data/meshes/tetrahedron-utf8-comment.ply
source "$here/shell_test_helpers.sh"
small=(--view-size 12 --random-rays 100 --aimed-rays 200 --stress-size 64)

"$rtusim" precision --triangles --mesh "$mesh" "${small[@]}" --n 12 --m 16 --E 4 --T 24 --C 4 \
  --csv tri.csv >tri.txt
grep -q "^c99 n=29 m=32 E=10 T=0 C=16 " tri.txt || fail "no prototype row: $(cat tri.txt)"
grep -q "^float32 watertight " tri.txt || fail "no float32 row: $(cat tri.txt)"
grep -q "^stress triangle" tri.txt || fail "no stress table: $(cat tri.txt)"
python3 - tri.csv <<'PY' || fail "CSV: $(cat tri.csv)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
mesh = [r for r in rows if r["study"] == "mesh"]
stress = [r for r in rows if r["study"] == "stress"]
# prototype, one row per swept value, vhdl, two unit-triangle dividers, two float32 tests
assert [r["swept"] for r in mesh] == ["", "n", "m", "E", "T", "C", "", "", "", "", ""], mesh
assert [r["format"] for r in mesh[1:6]] == [
    "c99 n=12 m=32 E=10 T=0 C=16", "c99 n=29 m=16 E=10 T=0 C=16", "c99 n=29 m=32 E=4 T=0 C=16",
    "c99 n=29 m=32 E=10 T=24 C=16", "c99 n=29 m=32 E=10 T=0 C=4"], mesh
assert len(stress) == 6 and all(r["swept"] == "" for r in stress), stress
rays = 4 * 144 + 100  # the aimed rays count only as edge rays
for r in rows:
    n = {k: int(r[k]) for k in ("rays", "reference_hits", "hits", "false_hits", "missed_hits",
                                "other_triangle", "edge_rays", "holes")}
    assert n["rays"] == (rays if r["study"] == "mesh" else 64 * 48), r
    # hits and reference hits differ by the false and the missed ones
    assert n["hits"] - n["reference_hits"] == n["false_hits"] - n["missed_hits"], r
    assert n["holes"] <= n["edge_rays"], r
    assert (r["self_hits_offset"] != "") == (r["arithmetic"] == "fixed"), r
for study in (mesh, stress):
    assert len({r["reference_hits"] for r in study}) == 1, study
# every aimed ray of a closed tetrahedron meets a shared edge or vertex first, from outside
assert 0 < int(mesh[0]["edge_rays"]) <= 200, mesh[0]
assert int(mesh[0]["reference_hits"]) > 0 and int(stress[0]["reference_hits"]) > 0
PY

expect_error "--triangles" "$rtusim" precision --mesh "$mesh" --n 12
expect_error "m must be in \[2, 32\], is 40" \
  "$rtusim" precision --triangles --mesh "$mesh" "${small[@]}" --m 40
expect_error "excludes" "$rtusim" precision --triangles --mesh "$mesh" --formats Q16.16
echo "triangle precision: ok"
