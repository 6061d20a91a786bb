#!/usr/bin/env bash
# FST traces (--trace t.fst, src/trace/fst_writer.cpp), read back with GTKWave's own fst2vcd: the
# same values in the same cycles as the VCD of the same run, for ideal and cached memory, an
# enum table that names the core states, and ray ids that follow every ray through the run. --vcd stays an alias of --trace. A --trace-scope that
# matches nothing is an error. Each trace comes with a GTKWave save file.
# Usage: fst_trace.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"
command -v fst2vcd >/dev/null || fail "fst2vcd not found: install gtkwave (scripts/setup.sh)"

"$rtusim" build --scene sphere --depth 5 --out sphere.svo >/dev/null
"$rtusim" jobs --width 16 --height 12 --out jobs.bin >/dev/null
normalise() { python3 "$here/vcd_normalise.py" "$1" 10000; }

for options in "--cores 4" "--cores 3 --memory cached"; do
  read -r -a run <<<"$options"
  replay=("$rtusim" replay --svo sphere.svo --jobs jobs.bin --out out.bin "${run[@]}")
  "${replay[@]}" --trace t.fst >/dev/null
  "${replay[@]}" --vcd v.vcd >/dev/null
  ! grep -q 'timescale' t.fst || fail "t.fst is a VCD"
  fst2vcd t.fst >from_fst.vcd
  [[ -s v.vcd ]] || fail "--vcd wrote no trace"
  normalise v.vcd >vcd.txt
  normalise from_fst.vcd >fst.txt
  (( $(wc -l <vcd.txt) > 1000 )) || fail "$options: the VCD holds only $(wc -l <vcd.txt) changes"
  cmp -s vcd.txt fst.txt || { diff vcd.txt fst.txt | head -5; fail "$options: FST and VCD differ"; }
done

# Ray ids (signal class ids), read back from the FST with fst2vcd: every ray followed from the
# host's input through one core to the host's output, in the output buffer's order.
python3 "$here/trace_ids_check.py" fst.txt out.bin || fail "the ray ids do not follow the run"
grep -qx '+{in ray} rtu.core_1.in.ray\[31:0\]' t.fst.gtkw || fail "t.fst.gtkw does not show the cores' ray ids"

# --trace-clock: rtu.clk high in the first half of every cycle of the window up to its last
# change, read back from the FST; first in the save file; counted by the dry run.
"$rtusim" replay --svo sphere.svo --jobs jobs.bin --out out.bin --cores 3 --trace clk.fst \
  --trace-clock --trace-from 100 --trace-to 140 >/dev/null
fst2vcd clk.fst >clk.vcd
python3 - clk.vcd <<'PY' || fail "rtu.clk is not a clock of period 10000 ps over the window"
import sys
code, time, edges = None, 0, []
for line in open(sys.argv[1]):
    words = line.split()
    if words[:1] == ["$var"] and words[4] == "clk":
        code = words[3]
    elif line.startswith("#"):
        time = int(line[1:])
    elif code and line.strip() in ("0" + code, "1" + code):
        edges.append((time, int(line[0])))
expected = [(cycle * 10000 + half * 5000, 1 - half) for cycle in range(100, 140) for half in (0, 1)]
assert edges == expected[:len(edges)] and len(edges) >= 70, edges[:6]
PY
grep -A2 -x '\[signals_width\] 240' clk.fst.gtkw | tail -2 | tr '\n' ' ' |
  grep -qx '@28 +{clk} rtu.clk ' || fail "clk.fst.gtkw does not show the clock first"
! grep -q 'clk' t.fst.gtkw || fail "a trace without --trace-clock has a clock"
"$rtusim" replay --svo sphere.svo --jobs jobs.bin --out out.bin --cores 2 --trace c.vcd \
  --trace-clock >report.txt
[[ $(sed -n 's/^trace size  c.vcd: .*(\([0-9]*\) bytes)$/\1/p' report.txt) == $(stat -c %s c.vcd) ]] ||
  fail "the dry run did not count the clock: $(grep 'trace size' report.txt), written $(stat -c %s c.vcd)"

# The save file next to the last trace: this trace, every signal of it, grouped per module in
# pipeline order, a marker at the first result.
[[ -f t.fst.gtkw ]] || fail "no save file t.fst.gtkw"
grep -qx "\[dumpfile\] \"$PWD/t.fst\"" t.fst.gtkw || fail "t.fst.gtkw does not open $PWD/t.fst"
groups=$(grep '^-' t.fst.gtkw | uniq | tr -d '-' | tr '\n' ' ')
[[ $groups == "job_manager scheduler core_0 core_1 core_2 memory result_manager " ]] ||
  fail "groups out of pipeline order: $groups"
grep -v '^[-@*[]' t.fst.gtkw | sed 's/^+{[^}]*} //; s/\[[0-9]*:0\]$//' | sort >shown.txt
awk '{ print $2 }' fst.txt | sort -u >traced.txt
cmp -s shown.txt traced.txt || fail "t.fst.gtkw does not show exactly the traced signals"
# Names within a group: the path below the module, apart by spaces (GTKWave cuts at dots).
grep -qx '+{in valid} rtu.core_1.in.valid' t.fst.gtkw && grep -qx '+{state} rtu.core_1.state\[2:0\]' t.fst.gtkw ||
  fail "t.fst.gtkw lacks the aliases within groups"
# Core states shown by the names of the FST's enum table: GTKWave's own flags for it.
[[ $(grep -B1 -x '+{state} rtu.core_1.state\[2:0\]' t.fst.gtkw | head -1) == @100000028 ]] ||
  fail "t.fst.gtkw does not show the core state by its enum names"
# A VCD has no enum table: its save file names the states through a translate filter beside it.
"$rtusim" replay --svo sphere.svo --jobs jobs.bin --out out.bin --cores 2 --trace v.vcd >/dev/null
[[ $(printf '%s\n' 000 001 010 011 100 101 110 111 | paste -d' ' - <(printf '%s\n' IDLE INIT EVAL NEXT PUSH POP OUT BLOCKED)) == "$(cat v.state.txt)" ]] ||
  fail "v.state.txt does not name the eight state codes"
grep -A2 -x '@2028' v.vcd.gtkw | grep -qx "\^1 $PWD/v.state.txt" || fail "v.vcd.gtkw does not use v.state.txt"
# Levels of the host's result handshake, cycle by cycle: the first cycle with both at 1.
first_result=$(python3 - fst.txt <<'PY'
import sys
level, changes = {}, {}
for line in open(sys.argv[1]):
    cycle, name, value = line.split()
    changes.setdefault(int(cycle), []).append((name, value))
for cycle in sorted(changes):
    level.update(changes[cycle])
    host = "rtu.result_manager.out."
    if level.get(host + "valid") == level.get(host + "ready") == "1":
        print(cycle)
        break
PY
)
# In cycles (the default at 100 MHz, 10 ns, which GTKWave keeps in ns): the marker at the first
# result's cycle, the view from the first cycle.
[[ $(awk '/^\*/ { print $2 }' t.fst.gtkw) == $((first_result * 10)) ]] ||
  fail "the marker is not at the first result (cycle $first_result)"
grep -qx '\[timestart\] 0' t.fst.gtkw || fail "the save file's view does not start at cycle 0"

# --trace-time: cycles by default at 100 MHz, picoseconds on demand (the same changes); cycles
# refused where a cycle is no timescale (150 MHz) or cannot hold a clock's edges.
grep -qx '\$timescale 10ns \$end' v.vcd || fail "the trace at 100 MHz is not in cycles (10 ns)"
"${replay[@]}" --vcd ps.vcd --trace-time ps >/dev/null
grep -qx '\$timescale 1ps \$end' ps.vcd || fail "--trace-time ps did not trace in picoseconds"
normalise ps.vcd >ps.txt
cmp -s ps.txt vcd.txt || fail "the trace in picoseconds holds other changes than the one in cycles"
expect_error "cannot show a traced clock" "${replay[@]}" --vcd c.vcd --trace-clock --trace-time cycles
expect_error "this clock's is 6667 ps" "${replay[@]}" --vcd c.vcd --clock-mhz 150 --trace-time cycles
"${replay[@]}" --vcd mhz150.vcd --clock-mhz 150 >/dev/null
grep -qx '\$timescale 1ps \$end' mhz150.vcd || fail "auto did not fall back to picoseconds at 150 MHz"

# rtusim wave: GTKWave (here a stand-in that prints its arguments) gets the trace and its save file.
expect_error "no such trace file: missing.fst" "$rtusim" wave missing.fst
expect_error "gtkwave not found on PATH" env PATH=/nonexistent "$rtusim" wave t.fst
mkdir bin && printf '#!/bin/sh\necho "$@"\n' >bin/gtkwave && chmod +x bin/gtkwave
expect_error "no display to open GTKWave on" env -u DISPLAY -u WAYLAND_DISPLAY PATH=$PWD/bin:$PATH \
  "$rtusim" wave t.fst
[[ $(DISPLAY=:99 PATH=$PWD/bin:$PATH "$rtusim" wave t.fst) == "t.fst t.fst.gtkw" ]] ||
  fail "rtusim wave did not open t.fst.gtkw"
# A VCD and an FST of the same name keep their own save files.
"$rtusim" replay --svo sphere.svo --jobs jobs.bin --out out.bin --cores 2 --trace t.vcd >/dev/null
[[ -f t.vcd.gtkw ]] && grep -qx "\[dumpfile\] \"$PWD/t.fst\"" t.fst.gtkw ||
  fail "t.vcd's save file overwrote t.fst's"

fst2vcd --extensions t.fst >extensions.vcd
grep -q 'IDLE INIT EVAL NEXT PUSH POP OUT BLOCKED 000 001 010 011 100 101 110 111' extensions.vcd ||
  fail "no enum table of the core states in the FST"
[[ $(grep -c '^\$attrbegin misc 07 "" 1' extensions.vcd) == 3 ]] ||
  fail "not every core's state refers to the enum table"
# --trace-scope (alias --vcd-scope): a scope that matches nothing fails, naming what exists.
expect_error "'rtu.core_7' matches no module" \
  "$rtusim" replay --svo sphere.svo --jobs jobs.bin --out out.bin --cores 4 --trace t.fst \
  --trace-scope rtu.core_7
grep -q "rtu.core_3.in" err.txt || fail "the scope error does not list rtu.core_3.in"
# Scopes and signal classes that together keep nothing: the job manager has no states.
expect_error "the trace would hold no signal: the scopes rtu.job_manager have none of the signal classes states" \
  "$rtusim" replay --svo sphere.svo --jobs jobs.bin --out out.bin --cores 4 --trace t.fst \
  --trace-scope rtu.job_manager --trace-signals states
echo "FST traces equal the VCD traces; core states named"
