#!/usr/bin/env bash
# Issue 32 end to end: jobs --ray-type writes secondary rays from a frame's hits, replay traces
# them on the cycle-accurate model as the golden model does (any-hit results keep bit 31 of the
# job word), render --passes runs them after the frame, fps and sweep rows hold them (workload.*
# keys), and bad settings are named.
# Usage: cli_secondary_rays.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"

"$rtusim" build --scene menger --depth 5 --out m.svo --model-header >build.txt
header=$(sed -n 's/^model header at word \([0-9]*\)$/\1/p' build.txt)
frame=(--width 24 --height 16)
"$rtusim" jobs --svo m.svo --model-address "$header" --ray-type shadow --rays shadow.bin \
  "${frame[@]}" --light 2.25,4,-2 --light -3,2.5,1 >jobs.txt
grep -q "primary hits of 384 pixels spawn" jobs.txt || fail "jobs --ray-type report"
records=$(( $(stat -c %s shadow.bin) / 32 ))
(( records > 100 )) || fail "too few shadow rays: $records"
# Every record has bit 31 (any-hit) of its first word set, none bit 30.
python3 - shadow.bin <<'PY' || fail "span bits of shadow records"
import struct, sys
data = open(sys.argv[1], "rb").read()
words = struct.unpack("<%dI" % (len(data) // 4), data)
assert all(words[i] >> 30 == 2 for i in range(0, len(words), 8))
PY
"$rtusim" golden --svo m.svo --rays shadow.bin --out golden.bin >/dev/null
"$rtusim" replay --preset cached --svo m.svo --rays shadow.bin --out ca.bin --stats s.json >ca.txt
grep -q "any_hit_rays" s.json || fail "any_hit_rays missing from the statistics"
python3 - golden.bin ca.bin s.json "$records" <<'PY' || fail "replay against golden"
import json, struct, sys
def records(path):
    data = open(path, "rb").read()
    words = struct.unpack("<%dI" % (len(data) // 4), data)
    return sorted(tuple(words[i:i + 8]) for i in range(0, len(words), 8))
golden, ca = records(sys.argv[1]), records(sys.argv[2])
assert golden == ca, "results differ"
assert all(r[0] >> 31 == 1 for r in ca), "bit 31 lost"
stats = json.load(open(sys.argv[3]))
assert stats["statistics"]["any_hit_rays"] == int(sys.argv[4])
assert stats["statistics"]["any_hit_hits"] == sum(r[1] for r in ca)
PY
# The same seed writes the same rays; orders keep them.
for type in ao diffuse; do
  "$rtusim" jobs --svo m.svo --model-address "$header" --ray-type $type --rays a.bin "${frame[@]}" \
    --samples 3 --seed 7 >/dev/null
  "$rtusim" jobs --svo m.svo --model-address "$header" --ray-type $type --rays b.bin "${frame[@]}" \
    --samples 3 --seed 7 --order shuffled >/dev/null
  "$rtusim" jobs --svo m.svo --model-address "$header" --ray-type $type --rays c.bin "${frame[@]}" \
    --samples 3 --seed 7 >/dev/null
  cmp -s a.bin c.bin || fail "$type rays are not reproducible"
  ! cmp -s a.bin b.bin || fail "$type shuffled is the pixel order"
  [[ $(stat -c %s a.bin) -eq $(stat -c %s b.bin) ]] || fail "$type shuffled lost rays"
done

# render --passes: a line per pass, the frame as one run, per-pass statistics files (each pass's
# window of the frame's run) summing to the frame's, an image; on the octree and a triangle kind.
for core in svo bvh; do
  "$rtusim" render --preset cached --core "$core" --scene menger --depth 5 "${frame[@]}" \
    --passes primary,shadow,ao --samples 2 --image m.png --stats r.json >render.txt
  grep -q "^pass        shadow" render.txt && grep -q "^pass        ao" render.txt ||
    fail "render --core $core --passes report"
  [[ -s m.png && -s r.json && -s r.shadow.json && -s r.ao.json && -s r.frame.json ]] ||
    fail "render --core $core --passes files"
  python3 - r.json r.shadow.json r.ao.json r.frame.json render.txt <<'PY' ||
import json, re, sys
def stat(path):
    s = json.load(open(path))
    return s["statistics"] if "statistics" in s else s
passes = [stat(p) for p in sys.argv[1:4]]
frame = stat(sys.argv[4])
line = [l for l in open(sys.argv[5]) if l.startswith("frame ") and "passes" in l][0]
rays, cycles = map(int, re.match(r"frame\s+(\d+) rays in 3 passes as one run, (\d+) cycles",
                                 line).groups())
assert (rays, cycles) == (frame["rays"], frame["total_cycles"])
for key in ("rays", "total_cycles"):
    assert frame[key] == sum(p[key] for p in passes), key
assert frame["memory"]["dram"]["bytes"] == sum(p["memory"]["dram"]["bytes"] for p in passes) > 0
PY
    fail "render --core $core: the passes do not sum to the frame"
done

# The key workload.rays in a configuration file, with the other workload keys.
printf '[workload]\nrays = "primary,shadow"\nlights = "2.25,4,-2;-3,2.5,1"\n' >w.toml
"$rtusim" render --model golden --config w.toml "${frame[@]}" | grep -q "^pass        shadow" ||
  fail "workload.rays from a file"

# fps and sweep rows of a frame with passes: the row's rays and cycles are the passes' sums, and
# each pass has its columns; the lights and samples keys change the shadow and ao passes.
"$rtusim" fps --config w.toml --scene menger --depth 5 --resolutions 24x16 --csv f.csv -j 1 \
  >/dev/null 2>&1
"$rtusim" sweep --scene menger --depth 5 "${frame[@]}" --grid workload.rays=primary,primary+ao \
  --grid workload.samples=1,2 --out s.csv -j 1 >/dev/null 2>&1
python3 - f.csv s.csv f.jsonl <<'PY' || fail "fps and sweep rows of passes"
import csv, json, sys
for line in open(sys.argv[3]):
    s = json.loads(line)["statistics"]
    assert s["total_cycles"] == sum(p["total_cycles"] for p in s["passes"].values()), s
for fps in csv.DictReader(open(sys.argv[1])):  # a row per core count
    assert int(fps["rays"]) == int(fps["primary_rays"]) + int(fps["shadow_rays"]) > 384, fps
    assert int(fps["primary_rays"]) == 384 and fps["ao_rays"] == "", fps
    assert float(fps["shadow_cycles_per_ray"]) > 0
rows = list(csv.DictReader(open(sys.argv[2])))
assert len(rows) == 4, len(rows)
ao = {int(r["workload.samples"]): int(r["ao_rays"]) for r in rows if r["workload.rays"] != "primary"}
assert ao[2] == 2 * ao[1] > 0, ao
for r in rows:
    if r["workload.rays"] == "primary":
        assert int(r["rays"]) == 384 and r["ao_rays"] == "", r
PY
"$rtusim" fps --core kd --scene menger --depth 5 --resolutions 24x16 --passes primary,shadow \
  --csv k.csv -j 1 >/dev/null 2>&1
python3 - k.csv <<'PY' || fail "fps --core kd rows of passes"
import csv, sys
for row in csv.DictReader(open(sys.argv[1])):
    assert int(row["rays"]) == 384 + int(row["shadow_rays"]) > 384, row
PY
# (into a file: grep -q leaving early would break the pipe under pipefail)
"$rtusim" config --list >keys.txt
grep -q "^workload.ao_distance" keys.txt || fail "config --list: workload keys"
expect_error "workload.samples" "$rtusim" render --scene menger --depth 5 "${frame[@]}" \
  --passes primary,ao --samples 0 --model golden

expect_error "--ray-type glossy" "$rtusim" jobs --svo m.svo --model-address "$header" \
  --ray-type glossy --rays x.bin
expect_error "give --svo" "$rtusim" jobs --model-address "$header" --ray-type ao --rays x.bin
expect_error "--samples must be 1 to 1024" "$rtusim" jobs --svo m.svo --model-address "$header" \
  --ray-type ao --samples 0 --rays x.bin
expect_error "first pass is primary" "$rtusim" render --scene menger --depth 5 "${frame[@]}" \
  --passes shadow --model golden
expect_error "--order sideways" "$rtusim" jobs --model-address 0 --rays x.bin --order sideways
echo "cli_secondary_rays: ok"
