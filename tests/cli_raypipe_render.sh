#!/usr/bin/env bash
# `rtusim render --architecture raypipe` end to end (issue 29): seed 001's ray pipe renders a voxel
# scene's faces, built into the Tray Racer's k-d tree, on its golden model at the seed's level 1
# (40x30): the report, the simple shader's image and the shaded one, --results-csv with the seed's
# pixel ids in the primary ray generator's order; the same rays from the scene built before (a k-d
# image, the seed's scene file: --accel-file); the trayracer preset; the same frame on the pipe's
# timed model (--model ca) with its cycles; --model lt refused before any work, and the pipe by
# a command that runs only the RTU; a ray pipe setting under the RTU reported as having no effect.
# Usage: cli_raypipe_render.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"
frame=(--scene sphere --depth 4 --index wide)

"$rtusim" render --architecture raypipe --model golden "${frame[@]}" --level 1 --image palette.png \
  --shaded-image shaded.png --cost-image cost.png --results-csv rays.csv >pipe.txt
grep -q "^frame       40x30 (level 1)" pipe.txt || fail "frame line: $(cat pipe.txt)"
hits=$(sed -n 's/^rays *1200: \([0-9]*\) box misses, \([0-9]*\) hits.*/\2/p' pipe.txt)
[[ -n $hits && $hits -gt 50 ]] || fail "report: $(cat pipe.txt)"
for image in palette.png shaded.png cost.png; do
  [[ -s $image ]] || fail "$image not written"
done

python3 - rays.csv "$hits" <<'PY' || fail "results CSV"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 1200, len(rows)
need = {"id", "x", "y", "hit", "box_miss", "t", "primitive", "u", "v", "nodes", "triangle_tests",
        "pushes", "restarts"}
assert need <= set(rows[0]), rows[0].keys()
# Issue order: the top-left 20x15 block first, its top row first, then block 2 to its right.
assert [(r["x"], r["y"]) for r in rows[:2]] == [("0", "0"), ("1", "0")], rows[:2]
assert (rows[300]["x"], rows[300]["y"]) == ("20", "0"), rows[300]
# The seed's pixel id is (rows - 1 - y_prg) cols + x: the row from the top times 40, plus x.
assert all(int(r["id"]) == int(r["y"]) * 40 + int(r["x"]) for r in rows)
assert sorted(int(r["id"]) for r in rows) == list(range(1200))
assert sum(r["hit"] == "1" for r in rows) == int(sys.argv[2])
for r in rows:
    if r["hit"] == "1":
        assert float(r["t"]) > 0 and r["primitive"] != "" and int(r["triangle_tests"]) > 0, r
    if r["box_miss"] == "1":
        assert r["hit"] == "0" and r["nodes"] == "0", r
PY

# The same scene built before, as a k-d image and as the seed's scene file: the same rays.
"$rtusim" build --accel kdtree "${frame[@]}" --out sphere.kd --trayracer-scene sphere.scene >build.txt
for file in sphere.kd sphere.scene; do
  "$rtusim" render --architecture raypipe --model golden --index wide --level 1 --accel-file $file \
    --results-csv $file.csv >$file.txt
  cmp -s rays.csv $file.csv || fail "--accel-file $file traces other rays than the build"
done
grep -q "^scene       sphere.scene: the Tray Racer's scene file (wide), 1488 triangles" \
  sphere.scene.txt || fail "scene file line: $(cat sphere.scene.txt)"
"$rtusim" render --architecture raypipe --model golden --index wide --level 1 \
  --accel-file sphere.scene --shaded-image file-shaded.png >/dev/null
[[ -s file-shaded.png ]] || fail "no shaded image from the scene file's normals"
expect_error "a k-d image holds none" "$rtusim" render --architecture raypipe --model golden \
  --index wide --level 0 --accel-file sphere.kd --shaded-image no.png

# The preset: the seed's camera registers at 640x480 (level 5) unless a level is given.
"$rtusim" render --preset trayracer --model golden "${frame[@]}" --level 0 >preset.txt
grep -q "^frame       20x15 (level 0)" preset.txt || fail "preset frame: $(cat preset.txt)"
grep -q "^camera      E 1.125,1.125,-1.25  U 1,0,0  V 0,1,0  W 0,0,1" preset.txt ||
  fail "preset camera: $(cat preset.txt)"

# --model ca: the same frame on the pipe's timed model. The same pixels as golden's; the report's
# frame cycles are the last exit + 1; the PRG takes at most one pixel every 3 cycles, in issue
# order; the shader lets out at most one pixel a cycle.
# (Depth 4: R1's build would leave nodes with two empty children there; rtusim's prunes them.)
small=(--scene sphere --depth 4 --index wide --level 1)
"$rtusim" render --architecture raypipe --model golden "${small[@]}" --image g3.png \
  --results-csv rays3.csv >/dev/null
"$rtusim" render --architecture raypipe --model ca "${small[@]}" --image ca.png \
  --results-csv ca.csv >ca.txt
cmp -s g3.png ca.png || fail "--model ca's image differs from golden's"
cycles=$(sed -n 's/^timing *\([0-9]*\) cycles at 50 MHz: .*/\1/p' ca.txt)
[[ -n $cycles ]] || fail "no timing line: $(cat ca.txt)"
grep -q "^busiest .* %;" ca.txt && grep -q "ray ids in flight at most" ca.txt &&
  grep -q "^writer  .* waited for the VGA reader (phase 0)" ca.txt || fail "ca report: $(cat ca.txt)"
# The busiest units by utilisation, as --stats has it: each unit's share of its full rate, per copy
# with two traversal units (their busy cycles are summed over both), so never above 100 %.
"$rtusim" render --architecture raypipe --model ca "${small[@]}" --set raypipe.traversal_units=2 \
  --stats two.json >two.txt
python3 - two.txt two.json <<'PY' || fail "busiest line: $(cat two.txt)"
import json, re, sys
line = [l for l in open(sys.argv[1]) if l.startswith("busiest")][0]
listed = [(u, float(p)) for u, p in re.findall(r" ([a-z_]+) ([0-9.]+) %;", line)]
units = {u["unit"]: 100 * u["utilisation"] for u in json.load(open(sys.argv[2]))["statistics"]["units"]}
assert len(listed) == 4 and all(0 < p <= 100 for _, p in listed), line
assert all(abs(units[u] - p) < 0.06 for u, p in listed), (listed, units)
assert listed[0][1] == round(max(units.values()), 1), (listed, units)
PY
python3 - rays3.csv ca.csv "$cycles" <<'PY' || fail "ca results CSV"
import csv, sys
golden, timed = (list(csv.DictReader(open(path))) for path in sys.argv[1:3])
assert [(r["id"], r["hit"], r["primitive"], r["t"]) for r in golden] == \
       [(r["id"], r["hit"], r["primitive"], r["t"]) for r in timed]
issue = [int(r["issue_cycle"]) for r in timed]
exits = [int(r["exit_cycle"]) for r in timed]
assert all(b - a >= 3 for a, b in zip(issue, issue[1:])), "the PRG took two pixels within 3 cycles"
assert len(set(exits)) == len(exits), "two pixels left the shader in one cycle"
assert all(e > i for i, e in zip(issue, exits))
assert max(exits) + 1 == int(sys.argv[3]), (max(exits), sys.argv[3])
PY
# --trace and --timeline of the timed pipe: sizes first, then a VCD with every unit's valid, stall
# and ray id and every FIFO's count, with its save file; the timeline's track per ray id. In the
# VCD (50 MHz: 20,000 ps a cycle), the PRG takes a pixel every third cycle at most and its pixel
# signal counts 0, 1, 2, ...; the pixel writer takes each pixel once; the timeline has a slice per
# ray from its id to its exit, as the results CSV's cycles say.
tiny=(--scene sphere --depth 4 --index wide --level 0)
sphere=(--scene sphere --depth 4 --index wide)
"$rtusim" render --architecture raypipe --model ca "${tiny[@]}" --trace t.vcd \
  --timeline t.json --results-csv traced.csv >traced.txt
grep -q "^trace size  t.vcd: " traced.txt && grep -q "^timeline    t.json: " traced.txt ||
  fail "trace sizes: $(cat traced.txt)"
[[ -s t.vcd && -s t.vcd.gtkw && -s t.json ]] || fail "trace, save file or timeline missing"
python3 - t.vcd t.json traced.csv <<'PY' || fail "trace or timeline content"
import csv, json, re, sys
text = open(sys.argv[1]).read()
ids, scope, names = {}, [], {}
for line in text.split("$enddefinitions")[0].splitlines():
    parts = line.split()
    if parts[:2] == ["$scope", "module"]: scope.append(parts[2])
    if parts[:1] == ["$upscope"]: scope.pop()
    if parts[:1] == ["$var"]: names[parts[3]] = ".".join(scope + [parts[4]])
assert "raypipe.trav.valid" in names.values() and "raypipe.fifos.tarb.count" in names.values()
history = {name: [] for name in names.values()}
time = 0
for line in text.split("$enddefinitions")[1].splitlines():
    if line.startswith("#"): time = int(line[1:]) // 20000; continue
    m = re.match(r"^b([01x]+) (\S+)$", line) or re.match(r"^([01x])(\S+)$", line)
    if m and m.group(2) in names: history[names[m.group(2)]].append((time, int(m.group(1), 2)))
rows = list(csv.DictReader(open(sys.argv[3])))
prg = [t for t, v in history["raypipe.prg.valid"] if v == 1]
assert len(prg) == len(rows) == 300, len(prg)
assert prg == sorted(int(r["issue_cycle"]) for r in rows)
assert all(b - a >= 3 for a, b in zip(prg, prg[1:]))
pixels = [v for t, v in history["raypipe.prg.pixel"]]
assert pixels == list(range(len(pixels))) and pixels[-1] == 299, pixels[-3:]
writes = [t for t, v in history["raypipe.pixel_writer.valid"] if v == 1]
assert 0 < len(writes) <= 300
events = json.load(open(sys.argv[2]))["traceEvents"]
slices = [e for e in events if e["ph"] == "X"]
assert len(slices) == 300, len(slices)
exits = {int(r["id"]): int(r["exit_cycle"]) for r in rows}
for e in slices:
    pixel = int(e["name"].split()[1])
    end = round((float(e["ts"]) + float(e["dur"])) * 50)  # microseconds at 50 MHz
    assert end == exits[pixel] + 1, (e, exits[pixel])
PY
# --trace-ray: the window of one ray, from the PRG's take to its exit.
"$rtusim" render --architecture raypipe --model ca "${tiny[@]}" --trace-ray 5 \
  --trace ray.fst >ray.txt
grep -q "^window      ray 5 (pixel 5, ray id [0-9]*): cycles 15 to [0-9]*" ray.txt ||
  fail "--trace-ray window: $(cat ray.txt)"
[[ -s ray.fst && -s ray.fst.gtkw ]] || fail "no FST"
expect_error "matches no module" "$rtusim" render --architecture raypipe --model ca "${tiny[@]}" \
  --trace bad.vcd --trace-scope raypipe.nosuch
expect_error "above --trace-max-mb 1" "$rtusim" render --architecture raypipe --model ca \
  "${sphere[@]}" --level 3 --trace big.vcd --trace-max-mb 1
[[ ! -e big.vcd ]] || fail "a refused trace was written"
expect_error "need --model ca or lt" "$rtusim" render --architecture raypipe --model golden \
  "${tiny[@]}" --trace golden.vcd
expect_error "no loosely-timed form" \
  "$rtusim" render --architecture raypipe --model lt "${frame[@]}" --level 0 --image lt.png
[[ ! -e lt.png ]] || fail "--model lt wrote an image"
expect_error "written for --architecture raypipe" \
  "$rtusim" render --model golden "${frame[@]}" --results-csv rtu.csv

# The commands that run only the RTU refuse the pipe rather than run the RTU in its place (fps,
# sweep and fidelity run it: cli_raypipe_explore.sh).
expect_error "rtusim accuracy runs the RTU only" "$rtusim" accuracy --preset trayracer

# A ray pipe setting with the RTU has no effect, and says so.
"$rtusim" render --model golden --scene sphere --depth 4 --width 16 --height 12 \
  --set raypipe.tmax_clamp=intended >rtu.txt 2>rtu.err
grep -q "raypipe.tmax_clamp (command line) has no effect: architecture is rtu" rtu.err ||
  fail "no-effect warning: $(cat rtu.err)"
echo "cli_raypipe_render: OK"
