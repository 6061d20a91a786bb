#!/usr/bin/env bash
# End-to-end use of the rtusim command: build, validate, jobs, golden, render, and clear errors
# with a non-zero exit for malformed inputs. Usage: cli_end_to_end.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"

"$rtusim" build --scene sphere --depth 6 --out sphere.svo | grep -q "descriptors" || fail "build report"
"$rtusim" validate sphere.svo | grep -q "valid" || fail "validate"
"$rtusim" jobs --width 32 --height 24 --out jobs.bin >/dev/null
[[ $(stat -c %s jobs.bin) -eq $((32 * 24 * 32)) ]] || fail "job buffer size"
"$rtusim" golden --svo sphere.svo --jobs jobs.bin --out results.bin | grep -q "rays        768" \
  || fail "golden report"
[[ $(stat -c %s results.bin) -eq $((32 * 24 * 32)) ]] || fail "result buffer size"
# Same rays, same scene: render and golden replay report the same hits and costs.
"$rtusim" golden --svo sphere.svo --jobs jobs.bin --out again.bin >golden.txt
"$rtusim" render --svo sphere.svo --width 32 --height 24 --image img.png --depth-image d.exr \
  --cost-image c.png >render.txt
[[ $(grep -E "^(hits|cost)" golden.txt) == $(grep -E "^(hits|cost)" render.txt) ]] \
  || fail "render and golden disagree"
cmp -s results.bin again.bin || fail "golden replay is not deterministic"
# The same results as CSV: a row per ray, the SVO's hits without primitive or barycentrics.
"$rtusim" golden --svo sphere.svo --jobs jobs.bin --results-csv results.csv >csv.txt
[[ $(head -1 results.csv) == "id,hit,t,primitive,u,v" && $(wc -l <results.csv) -eq 769 ]] ||
  fail "results CSV shape"
hits=$(sed -n 's/^hits *\([0-9]*\) .*/\1/p' csv.txt)
[[ $(grep -c '^[0-9]*,1,[0-9.e+-]*,,,$' results.csv) -eq $hits && $hits -gt 0 ]] ||
  fail "results CSV hits"
[[ -s img.png && -s d.exr && -s c.png ]] || fail "images missing"

# An animated model: the sphere moved by T = (10,-5,3), turned 90 degrees about y and scaled by 2,
# seen from the default camera moved the same way, looks exactly as the unmoved sphere does.
"$rtusim" build --scene sphere --depth 6 --out moved.svo --model-header --translate 10,-5,3 \
  --rotate-deg 0,90,0 --scale 2,2,2 >build.txt
header=$(sed -n 's/^model header at word \([0-9]*\)$/\1/p' build.txt)
[[ -n $header && $(stat -c %s moved.svo) -eq $(( (header + 16) * 4 )) ]] || fail "model header"
"$rtusim" jobs --width 32 --height 24 --camera 4.8,-2.4,6.8 --look-at 10,-5,3 --rays rays.bin \
  --model-address "$header" | grep -q "768 ray records" || fail "jobs --rays report"
[[ $(stat -c %s rays.bin) -eq $((32 * 24 * 32)) ]] || fail "ray buffer size"
"$rtusim" golden --svo moved.svo --rays rays.bin --out moved.bin >moved.txt
[[ $(grep -E "^(hits|cost)" moved.txt) == $(grep -E "^(hits|cost)" golden.txt) ]] \
  || fail "the moved model does not look like the unmoved one"

printf 'garbage' >bad.svo
expect_error "not a multiple" "$rtusim" validate bad.svo
printf '\x01\x00\x00\x00' >leaf_not_valid.svo  # valid=0, leaf=1 in slot 0
expect_error "slot 0" "$rtusim" validate leaf_not_valid.svo
head -c 100 jobs.bin >short.bin
expect_error "not a multiple" "$rtusim" golden --svo sphere.svo --jobs short.bin --out x.bin
expect_error "is not one of sphere|shell" "$rtusim" build --scene nope --out x.svo
expect_error "one scene" "$rtusim" render --svo sphere.svo --mesh jobs.bin
expect_error "three numbers" "$rtusim" render --camera 1,2
expect_error "fraction bits" "$rtusim" golden --svo sphere.svo --jobs jobs.bin --out x.bin \
  --fraction-bits 40
expect_error "width: 0 is out of range" "$rtusim" jobs --width 0 --out x.bin
expect_error "requires --model-header" "$rtusim" build --scene sphere --out x.svo --translate 1,2,3
expect_error "scale y is 0" "$rtusim" build --scene sphere --out x.svo --model-header --scale 1,0,1
expect_error "three numbers" "$rtusim" build --scene sphere --out x.svo --model-header --rotate-deg 1,2
expect_error "requires --model-address" "$rtusim" jobs --rays x.bin
expect_error "give --out" "$rtusim" jobs --width 4 --height 4
expect_error "excludes" "$rtusim" golden --svo moved.svo --jobs jobs.bin --rays rays.bin --out x.bin
expect_error "past the end" "$rtusim" golden --svo sphere.svo --rays rays.bin --out x.bin
expect_error "bits 31:28" "$rtusim" golden --svo moved.svo --rays jobs.bin --out x.bin
head -c 100 rays.bin >short_rays.bin
expect_error "not a multiple" "$rtusim" golden --svo moved.svo --rays short_rays.bin --out x.bin
# The cycle-accurate model: same results as the golden model (in arrival order), statistics JSON
# with the total cycle count, and a VCD trace; ray records through the job manager likewise.
sorted_records() { od -An -v -tx4 -w32 "$1" | sort; }
for memory in ideal cached; do
  "$rtusim" replay --svo sphere.svo --jobs jobs.bin --out replay.bin --cores 4 --memory "$memory" \
    --stats stats.json --vcd trace.vcd --vcd-to 200 --vcd-scope rtu.core_1 >replay.txt
  # The cost is the state count with any memory; blocked cycles are reported beside it.
  [[ $(sorted_records replay.bin) == $(sorted_records results.bin) ]] \
    || fail "replay ($memory) differs from golden"
  grep -q '"total_cycles": [1-9]' stats.json || fail "stats JSON without total_cycles"
  grep -q 'enddefinitions' trace.vcd && grep -q 'core_1' trace.vcd && ! grep -q 'core_0' trace.vcd \
    || fail "VCD scope filter"
done
# `rtusim stats --list` names every key of the statistics JSON (here with cached memory), with
# its unit, combination and doc (issue 26).
"$rtusim" stats --list >stats_list.txt
unlisted=$(LC_ALL=C comm -23 <(python3 "$here/statistics_keys.py" stats.json) \
  <(awk '!/^#/ && NF >= 4 {print $1}' stats_list.txt | LC_ALL=C sort -u))
[[ -z $unlisted ]] || fail "stats --list does not list: $unlisted"
expect_error "give --list" "$rtusim" stats
"$rtusim" golden --svo moved.svo --rays rays.bin --out golden_rays.bin >/dev/null
"$rtusim" replay --svo moved.svo --rays rays.bin --out replay_rays.bin --scheduler fa >/dev/null
[[ $(sorted_records replay_rays.bin) == $(sorted_records golden_rays.bin) ]] \
  || fail "replay of ray records differs from golden"
# Formats over 32 bits end to end (issue 11): 12-word result records, golden and replay agree, and
# each hit's t is the Q16.16 one to within a few of its steps (t in units of 2^-fraction).
"$rtusim" golden --svo sphere.svo --jobs jobs.bin --out q16.bin >/dev/null
for format in 40.24 48.32; do
  bits=(${format/./ })
  "$rtusim" golden --svo sphere.svo --jobs jobs.bin --out "g$format.bin" \
    --total-bits "${bits[0]}" --fraction-bits "${bits[1]}" >/dev/null
  "$rtusim" replay --svo sphere.svo --jobs jobs.bin --out "r$format.bin" --cores 4 \
    --total-bits "${bits[0]}" --fraction-bits "${bits[1]}" >/dev/null
  [[ $(stat -c %s "g$format.bin") -eq $((32 * 24 * 48)) ]] || fail "$format result buffer size"
  [[ $(od -An -v -tx4 -w48 "r$format.bin" | sort) == $(od -An -v -tx4 -w48 "g$format.bin" | sort) ]] \
    || fail "replay differs from golden in $format"
  python3 - "g$format.bin" "${bits[1]}" q16.bin <<'PY' || fail "$format t-values differ from Q16.16"
import struct, sys
wide, fraction = open(sys.argv[1], "rb").read(), int(sys.argv[2])
narrow = open(sys.argv[3], "rb").read()
hits = 0
for i in range(len(narrow) // 32):
    n = struct.unpack_from("<8I", narrow, 32 * i)
    w = struct.unpack_from("<2I4q2I", wide, 48 * i)
    assert w[0] == n[0] and w[1] == n[1], i
    if n[1]:
        hits += 1
        t16 = struct.unpack("<i", struct.pack("<I", n[2]))[0] / 2.0**16
        assert abs(w[2] / 2.0**fraction - t16) < 4 / 2.0**16, (i, w[2], t16)
        assert sorted(w[3:6]) == [0, 0, 2**fraction], i
assert hits > 0
PY
done
# A record with a NaN t-value is skipped with a warning naming it; the rest is traced (issue 11).
python3 - jobs.bin nan_jobs.bin <<'PY'
import struct, sys
words = bytearray(open(sys.argv[1], "rb").read())
struct.pack_into("<I", words, 32 * 5 + 8, 0x7FC00000)  # t0y of record 5
open(sys.argv[2], "wb").write(words)
PY
for command in golden replay; do
  "$rtusim" $command --svo sphere.svo --jobs nan_jobs.bin --out "nan_$command.bin" >nan.txt \
    || fail "$command stopped at a NaN record"
  grep -q "job buffer 'nan_jobs.bin': record 5: t-value on axis y is NaN; skipped" nan.txt \
    || fail "$command does not name the NaN record"
  [[ $(stat -c %s "nan_$command.bin") -eq $((767 * 32)) ]] || fail "$command skipped more than one"
  [[ $(sorted_records "nan_$command.bin") == $(od -An -v -tx4 -w32 results.bin | sed 6d | sort) ]] \
    || fail "$command traced the other records differently"
done
# render defaults to the SystemC model and reports the frame rate at the clock.
"$rtusim" render --svo sphere.svo --width 32 --height 24 --clock-mhz 200 >sc_render.txt
grep -q "at 200.00 MHz" sc_render.txt || fail "render frame rate"
[[ $(grep -E "^(hits|cost)" sc_render.txt) == $(grep -E "^(hits|cost)" golden.txt) ]] \
  || fail "SystemC render and golden disagree"
expect_error "cores: 0 is out of range 1 .. 1024" "$rtusim" replay --svo sphere.svo --jobs jobs.bin --out x.bin --cores 0
expect_error "do not hold one 32-byte line" "$rtusim" replay --svo sphere.svo --jobs jobs.bin --out x.bin \
  --memory cached --l1-size 16
expect_error "stack frames" "$rtusim" replay --svo sphere.svo --jobs jobs.bin --out x.bin \
  --stack-frames 2
"$rtusim" replay --svo sphere.svo --jobs jobs.bin --out x.bin --stack-frames 2 \
  --allow-stack-overflow 2>/dev/null | grep -q "stack overflows" || fail "overflows not reported"
expect_error "clock_mhz: 0 is out of range" "$rtusim" render --scene sphere --depth 4 --clock-mhz 0
expect_error "give the input" "$rtusim" replay --svo sphere.svo --out x.bin
# One flag, one meaning (issue 26): --ray-epsilon is job_manager.epsilon, --camera-epsilon is
# camera.epsilon. --epsilon still spells the one a command has; in `config`, which has both, it is
# deprecated and sets job_manager.epsilon as before, with a warning naming the new flags.
"$rtusim" config --list >list.txt
grep -Eq '^job_manager\.epsilon +--ray-epsilon ' list.txt || fail "config --list: --ray-epsilon"
grep -Eq '^camera\.epsilon +--camera-epsilon ' list.txt || fail "config --list: --camera-epsilon"
dump_epsilons() {  # dump_epsilons FLAGS...: "job_manager camera" epsilons of config --dump
  "$rtusim" config --dump --json "$@" 2>err.txt | python3 -c \
    'import json,sys; d=json.load(sys.stdin); print(d["job_manager.epsilon"], d["camera.epsilon"])'
}
[[ $(dump_epsilons --ray-epsilon 0.002) == "0.002 0.0001" ]] || fail "--ray-epsilon"
! grep -q deprecated err.txt || fail "--ray-epsilon warned"
[[ $(dump_epsilons --camera-epsilon 0.003) == "0.0001 0.003" ]] || fail "--camera-epsilon"
[[ $(dump_epsilons --epsilon 0.004) == "0.004 0.0001" ]] || fail "config --epsilon changed meaning"
grep -q -- "--epsilon is ambiguous in rtusim config and deprecated: it sets job_manager.epsilon" \
  err.txt && grep -q -- "--ray-epsilon (job_manager.epsilon) or --camera-epsilon (camera.epsilon)" \
  err.txt || fail "config --epsilon without the deprecation warning"
# Where a command has one of the two, --epsilon is that one, silently; the other is refused.
for flag in --epsilon --ray-epsilon; do
  "$rtusim" golden --svo moved.svo --rays rays.bin --out "eps$flag.bin" "$flag" 0.5 >/dev/null 2>err.txt
  ! grep -q deprecated err.txt || fail "golden $flag warned"
done
cmp -s eps--epsilon.bin eps--ray-epsilon.bin || fail "golden --epsilon is not --ray-epsilon"
! cmp -s eps--epsilon.bin golden_rays.bin || fail "golden --ray-epsilon 0.5 had no effect"
# A 9x9 frame looking down the z axis: its middle row and column have exactly zero components.
for flag in --epsilon --camera-epsilon; do
  "$rtusim" jobs --width 9 --height 9 --camera 0,0,-3 --out "eps$flag.bin" "$flag" 0.25 \
    >/dev/null 2>err.txt
  ! grep -q deprecated err.txt || fail "jobs $flag warned"
done
"$rtusim" jobs --width 9 --height 9 --camera 0,0,-3 --out eps_default.bin >/dev/null
cmp -s eps--epsilon.bin eps--camera-epsilon.bin || fail "jobs --epsilon is not --camera-epsilon"
! cmp -s eps--epsilon.bin eps_default.bin || fail "jobs --camera-epsilon 0.25 had no effect"
expect_error "camera-epsilon" "$rtusim" golden --svo moved.svo --rays rays.bin --out x.bin \
  --camera-epsilon 0.5
expect_error "ray-epsilon" "$rtusim" jobs --width 8 --height 8 --out x.bin --ray-epsilon 0.5
echo "cli end-to-end: ok"
