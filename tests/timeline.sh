#!/usr/bin/env bash
# The --timeline (src/trace/timeline_writer.h) against the run's statistics and the golden model's
# costs (tests/timeline_check.py), for ideal and cached memory, with and without a reorder buffer;
# a windowed timeline is that window cut from the full one;
# the dry run's sizes (src/run/trace_plan.h) equal the files written; --trace-max-mb refuses a
# file before writing it, naming the options that narrow it; --trace-ray's window runs from the
# ray's handshake into the job manager to its result's handshake with the host, checked in a full
# trace and in the output buffer's arrival order.
# Usage: timeline.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"

"$rtusim" build --scene sphere --depth 5 --out sphere.svo >/dev/null
"$rtusim" jobs --width 16 --height 12 --out jobs.bin >/dev/null
"$rtusim" golden --svo sphere.svo --jobs jobs.bin --out golden.bin >/dev/null
replay=("$rtusim" replay --svo sphere.svo --jobs jobs.bin --out out.bin)

"${replay[@]}" --cores 3 --timeline ideal.json --stats ideal.stats >/dev/null
python3 "$here/timeline_check.py" ideal.json ideal.stats golden.bin
for options in "--cores 4" "--cores 12 --scheduler rr --reorder 8"; do
  read -r -a run <<<"$options"
  "${replay[@]}" "${run[@]}" --memory cached --timeline t.json --trace t.vcd --stats t.stats >report.txt
  python3 "$here/timeline_check.py" t.json t.stats golden.bin --cached
  for file in t.json t.vcd; do
    measured=$(grep -o "$file: .*(\([0-9]*\) bytes)" report.txt | grep -o '[0-9]* bytes' | cut -d' ' -f1)
    [[ $measured == $(stat -c %s $file) ]] || fail "$options: dry run measured $file as '$measured' bytes, written $(stat -c %s $file)"
  done
done
grep -q '"name":"core_03"' t.json || fail "track names not zero-padded for 12 cores"

# A windowed timeline is that window cut from the full timeline: the rays that start in it with
# the slices nested in them, nothing else, and each counter's value in every cycle of it.
"${replay[@]}" --cores 4 --memory cached --timeline whole.json >/dev/null
"${replay[@]}" --cores 4 --memory cached --timeline part.json --trace-from 300 --trace-to 700 >/dev/null
python3 - whole.json part.json 300 700 <<'PY' || fail "a windowed timeline is not the window cut from the full one"
import json, sys
whole, part = (json.load(open(p))["traceEvents"] for p in sys.argv[1:3])
first, end = int(sys.argv[3]), int(sys.argv[4])
def cycle(e):
    return round(e["ts"] * 100)  # 100 MHz
def ends(e):
    return round((e["ts"] + e["dur"]) * 100)
def cut(events):
    """The ray slices that start in the window and the slices nested in them, on their core."""
    kept = set()
    slices = [e for e in events if e["ph"] == "X"]
    for ray in slices:
        if not ray["name"].startswith("ray ") or not first <= cycle(ray) < end:
            continue
        for e in slices:
            if e["tid"] == ray["tid"] and cycle(ray) <= cycle(e) and ends(e) <= ends(ray):
                kept.add((e["tid"], e["name"], e["ts"], e["dur"]))
    return kept
kept = cut(part)
assert kept and kept == cut(whole)
assert len(kept) == sum(e["ph"] == "X" for e in part)
def samples(events, name):
    return sorted((cycle(e), list(e["args"].values())[0]) for e in events if e["ph"] == "C" and e["name"] == name)
def value(steps, c):
    held = None
    for at, v in steps:
        if at > c:
            break
        held = v
    return held
names = {e["name"] for e in whole if e["ph"] == "C"}
assert names == {e["name"] for e in part if e["ph"] == "C"}
for name in names:
    full, windowed = samples(whole, name), samples(part, name)
    assert first <= windowed[0][0] and windowed[-1][0] < end, name
    for c in range(windowed[0][0], end):
        assert value(full, c) == value(windowed, c), (name, c)
PY

# Refused before anything is written, with the options that narrow it (64x48: about 2 MB each).
"$rtusim" jobs --width 64 --height 48 --out jobs64.bin >/dev/null
large=("$rtusim" replay --svo sphere.svo --jobs jobs64.bin --out out64.bin --memory cached)
expect_error "trace t2.vcd would be about .*--trace-scope, --trace-from/--trace-to, --trace-ray" \
  "${large[@]}" --trace t2.vcd --trace-max-mb 1
[[ ! -e t2.vcd ]] || fail "a refused trace was written"
expect_error "timeline t2.json would be about .*--trace-from/--trace-to or --trace-ray" \
  "${large[@]}" --timeline t2.json --trace-max-mb 1
[[ ! -e t2.json ]] || fail "a refused timeline was written"
expect_error "--trace-ray needs --trace or --timeline" "${replay[@]}" --trace-ray 3
expect_error "the input has 192 rays" "${replay[@]}" --trace t3.vcd --trace-ray 192

# --trace-ray 100: the window's first cycle is the 101st job handshake into the job manager, its
# last the handshake of the 100th job's result with the host, in the full trace of the same run.
"${replay[@]}" --cores 4 --memory cached --trace full.vcd >/dev/null
"${replay[@]}" --cores 4 --memory cached --trace ray.vcd --timeline ray.json --trace-ray 100 >report.txt
read -r from to core < <(sed -n 's/^window *ray 100: cycles \([0-9]*\) to \([0-9]*\), on core \([0-9]*\)$/\1 \2 \3/p' report.txt)
[[ -n ${to:-} ]] || fail "no window reported: $(cat report.txt)"
python3 "$here/vcd_normalise.py" full.vcd 10000 >full.txt
python3 - full.txt out.bin "$from" "$to" "$core" <<'PY' || fail "--trace-ray window"
import struct, sys
changes, out, first, last, core = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
levels = {}
for line in open(changes):
    cycle, name, value = line.split()
    levels.setdefault(name, []).append((int(cycle), 0 if value == "x" else int(value)))
def transfers(channel):
    """Cycles in which channel.valid and channel.ready are both high."""
    changes = sorted([(c, "v", v) for c, v in levels[channel + ".valid"]] +
                     [(c, "r", v) for c, v in levels[channel + ".ready"]])
    state, cycles, since = {"v": 0, "r": 0}, [], 0
    for cycle, which, value in changes + [(10**9, "v", 0)]:
        if state["v"] and state["r"]:
            cycles.extend(range(since, cycle))
        state[which], since = value, cycle
    return sorted(set(cycles))
entries = transfers("rtu.job_manager.in")
words = struct.unpack("<%dI" % (len(open(out, "rb").read()) // 4), open(out, "rb").read())
order = [words[i] & 0x0FFFFFFF for i in range(0, len(words), 8)]
results = transfers("rtu.result_manager.out")
assert entries[100] == first, (entries[100], first)
assert results[order.index(100)] == last, (results[order.index(100)], last)
def level(name, cycle):
    """The value of signal `name` in `cycle`."""
    value = None
    for c, v in levels[name]:
        if c > cycle: break
        value = v
    return value
took = [n for n in range(4) if any(level("rtu.core_%d.in.ray" % n, c) == 100 for c in transfers("rtu.core_%d.in" % n))]
assert took == [core], (took, core)
PY
[[ $(grep -m1 '^-' ray.vcd.gtkw) == "-core_$core" ]] || fail "the save file does not show core $core first"
# The save file opens on the window (a trace in cycles at 100 MHz, which GTKWave keeps in ns: ten
# units a cycle): from its first cycle, zoomed so GTKWave's window of the save file's size
# (4.3 * 2^-zoom units wide, measured) holds the window with at most 10 % to spare, the marker at
# the ray's result.
python3 - ray.vcd.gtkw "$from" "$to" <<'PY' || fail "--trace-ray save file view"
import sys
lines, first, last = open(sys.argv[1]).read().split("\n"), int(sys.argv[2]), int(sys.argv[3])
assert "[size] 1400 900" in lines
assert "[timestart] %d" % (10 * first) in lines, lines[:4]
zoom, marker = [l.split()[:2] for l in lines if l.startswith("*")][0]
shown = 4.3 * 2 ** -float(zoom[1:])
assert 10 * (last + 1 - first) <= shown <= 11 * (last + 1 - first), (shown, first, last)
assert int(marker) == 10 * last, (marker, last)
PY
grep -qx '\$timescale 10ns \$end' ray.vcd || fail "a trace at 100 MHz is not in cycles"
python3 - ray.json "$from" "$to" <<'PY' || fail "--trace-ray timeline"
import json, sys
events, first, last = json.load(open(sys.argv[1]))["traceEvents"], int(sys.argv[2]), int(sys.argv[3])
rays = [e for e in events if e["ph"] == "X" and e["name"].startswith("ray ")]
assert any(e["name"] == "ray 100" for e in rays)
assert all(first <= round(e["ts"] * 100) <= last for e in rays), "a ray starts outside the window"
PY
echo "timeline: ok"
