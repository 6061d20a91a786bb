#!/usr/bin/env bash
# Recorded workloads in fps and sweep (issue 31 section 2): `--set jobs=FILE` (and `rays=FILE`)
# runs the buffer's records instead of the camera's frame, with the same cycles as `replay` of
# that buffer on the same image; fps shows the buffer in place of a resolution and refuses
# --resolutions beside it; the rows carry the buffer in their configuration.
# Usage: recorded_workloads.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"

"$rtusim" build --scene sphere --depth 4 --out sphere.svo >/dev/null
# A view from another side than the default camera's, so the buffer is not the default frame.
"$rtusim" jobs --width 24 --height 16 --camera 2,1,2 --out jobs.bin >/dev/null
"$rtusim" replay --svo sphere.svo --jobs jobs.bin --out out.bin --cores 4 --memory cached \
  --stats replay.json >/dev/null
cycles=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["statistics"]["total_cycles"])' replay.json)

"$rtusim" sweep --svo sphere.svo --set jobs=jobs.bin --memory cached --grid cores=1,4 \
  --out sweep.csv -j 1 >/dev/null
python3 - sweep.csv sweep.jsonl "$cycles" <<'PY' || fail "sweep over a recorded job buffer"
import csv, json, sys
rows = {r["cores"]: r for r in csv.DictReader(open(sys.argv[1]))}
assert rows["4"]["total_cycles"] == sys.argv[3], (rows["4"]["total_cycles"], sys.argv[3])
assert rows["4"]["rays"] == rows["1"]["rays"] == "384", rows["4"]["rays"]
assert int(rows["1"]["total_cycles"]) > int(rows["4"]["total_cycles"])
assert all(json.loads(line)["config"]["jobs"] == "jobs.bin" for line in open(sys.argv[2]))
PY

"$rtusim" fps --svo sphere.svo --set jobs=jobs.bin --memory cached --cores 4 --csv fps.csv >fps.txt
grep -q "^jobs.bin *4 *384 *$cycles " fps.txt || fail "fps row of the buffer: $(cat fps.txt)"
[[ $(sed -n 2p fps.csv | cut -d, -f1-5) == ",,4,384,$cycles" ]] || fail "fps CSV row: $(sed -n 2p fps.csv)"
expect_error "a recorded workload (jobs.bin) has its own rays" \
  "$rtusim" fps --svo sphere.svo --set jobs=jobs.bin --resolutions 64x48
expect_error "jobs excludes rays" \
  "$rtusim" sweep --svo sphere.svo --set jobs=jobs.bin --rays jobs.bin --out x.csv -j 1
echo "recorded workloads: ok"
