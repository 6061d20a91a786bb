#!/usr/bin/env bash
# FST traces (--trace t.fst, modules/fst_writer.cpp), read back with GTKWave's own fst2vcd: the
# same values in the same cycles as the VCD of the same run, for ideal and cached memory, and an
# enum table that names the core states. --vcd stays an alias of --trace. A --trace-scope that
# matches nothing is an error.
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
  "${replay[@]}" --vcd t.vcd >/dev/null
  ! grep -q 'timescale' t.fst || fail "t.fst is a VCD"
  fst2vcd t.fst >from_fst.vcd
  [[ -s t.vcd ]] || fail "--vcd wrote no trace"
  normalise t.vcd >vcd.txt
  normalise from_fst.vcd >fst.txt
  (( $(wc -l <vcd.txt) > 1000 )) || fail "$options: the VCD holds only $(wc -l <vcd.txt) changes"
  cmp -s vcd.txt fst.txt || { diff vcd.txt fst.txt | head -5; fail "$options: FST and VCD differ"; }
done
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
echo "FST traces equal the VCD traces; core states named"
