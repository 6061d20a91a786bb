#!/usr/bin/env bash
# Issue 28 §2: `replay` of triangle ray records on the BVH, BIH and k-d cores. Ray records of a
# camera looking at the spider (naming model address 0, as golden's), replayed through each image
# file on the cycle-accurate model (4 cores, triangle units shared by 2) and the loosely-timed one
# (cached): the CSV rows, sorted by id, are golden's (golden --accel-file), and the k-d core hits
# the BVH's triangles.
# Refusals name the mismatch: an image of another kind, a record naming a model header, --svo.
# Usage: cli_triangle_replay.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"
spider=/usr/share/assimp/models/OBJ/spider.obj

"$rtusim" build --accel bvh --mesh "$spider" --drop-bad-triangles --out s.bvh >/dev/null
"$rtusim" build --accel bih --index wide --mesh "$spider" --drop-bad-triangles --out s.bih \
  >/dev/null 2>&1
"$rtusim" build --accel kdtree --index wide --mesh "$spider" --drop-bad-triangles --out s.kd \
  >/dev/null 2>&1
"$rtusim" jobs --width 24 --height 16 --camera 0,40,260 --look-at 0,0,0 --fov 30 --rays rays.bin \
  --model-address 0 >/dev/null

# The BIH's records are grid coordinates: the spider's float32 box onto its grid.
python3 "$here/bih_grid_rays.py" s.bvh s.bih rays.bin grid_rays.bin

same_rows() {  # same_rows a.csv b.csv what: the rows sorted by id, and some hits
  python3 - "$1" "$2" <<'PY' || fail "$3: $1 differs from $2"
import csv, sys
a, b = (sorted(csv.DictReader(open(p)), key=lambda r: int(r["id"])) for p in sys.argv[1:3])
assert len(a) == 384 and a == b, (len(a), len(b))
assert sum(r["hit"] == "1" for r in a) > 30
PY
}

"$rtusim" golden --accel-file s.bvh --rays rays.bin --results-csv bvh_golden.csv >/dev/null
"$rtusim" golden --accel-file s.bih --rays grid_rays.bin --results-csv bih_golden.csv >/dev/null
"$rtusim" golden --accel-file s.kd --rays rays.bin --results-csv kd_golden.csv >/dev/null
for core in bvh bih kd; do
  image=s.$core rays=rays.bin
  [[ $core == bih ]] && rays=grid_rays.bin
  "$rtusim" replay --core "$core" --accel-file "$image" --rays "$rays" --out "${core}_ca.csv" \
    --cores 4 --triangle-shared-by 2 --stats "${core}_ca.json" >"${core}_ca.txt"
  grep -q "^rays        384$" "${core}_ca.txt" || fail "$core replay report: $(cat "${core}_ca.txt")"
  same_rows "${core}_ca.csv" "${core}_golden.csv" "$core cycle-accurate"
  "$rtusim" replay --core "$core" --accel-file "$image" --rays "$rays" --out "${core}_lt.csv" \
    --model lt --memory cached >/dev/null
  same_rows "${core}_lt.csv" "${core}_golden.csv" "$core loosely-timed"
done
python3 - bvh_ca.json <<'PY' || fail "statistics of the shared units"
import json, sys
stats = json.load(open(sys.argv[1]))
assert stats["config"]["core.triangle.shared_by"] == 2, stats["config"]
PY

# The k-d core hits the BVH's triangles (float24 matrices against float32 vertices: a ray near an
# edge may go either way).
python3 - kd_ca.csv bvh_golden.csv <<'PY' || fail "k-d replay against the BVH's"
import csv, sys
kd, bvh = ({r["id"]: r for r in csv.DictReader(open(p))} for p in sys.argv[1:3])
same = sum(kd[i]["hit"] == bvh[i]["hit"] and kd[i]["primitive"] == bvh[i]["primitive"] for i in kd)
assert same >= 0.95 * len(kd), same
PY

expect_error "is a bvh image, and --core is kd" \
  "$rtusim" replay --core kd --accel-file s.bvh --rays rays.bin --out x.csv
python3 -c "
import sys; raw = open('rays.bin', 'rb').read(); open('bad.bin', 'wb').write(raw[:28] + b'\x07\0\0\0')"
expect_error "record 0 names model address 7; an image file has no model headers: give 0" \
  "$rtusim" replay --core bvh --accel-file s.bvh --rays bad.bin --out x.csv
expect_error "--svo is the SVO core's image" \
  "$rtusim" replay --core bvh --svo s.bvh --accel-file s.bvh --rays rays.bin --out x.csv
expect_error "give --rays" "$rtusim" replay --core bih --accel-file s.bih --out x.csv
echo "triangle replay: ok"
