#!/usr/bin/env bash
# Settings that cannot work are refused before any long work starts, with a message naming the
# option (issue 12, docs/robustness.md). Usage: settings_checks.sh path/to/rtusim
set -euo pipefail
rtusim=$1
source "$(dirname "${BASH_SOURCE[0]}")/shell_test_helpers.sh"

"$rtusim" build --scene sphere --depth 5 --out sphere.svo >/dev/null
"$rtusim" jobs --width 8 --height 8 --out jobs.bin >/dev/null
cp jobs.bin jobs_copy.bin

# Rates, latencies and the clock: ranges the arithmetic supports (1e-18 used to overflow into a
# fast bus, 1e-300 behaved as unlimited, 1e-12 MHz overflowed picosecond time).
expect_error "memory.dram.bytes_per_cycle: 1e-18 is out of range 0.001 .. 1e+06" \
  "$rtusim" render --scene sphere --depth 4 --memory cached --dram-bytes-per-cycle 1e-18
expect_error "host.in.bytes_per_cycle: 1e-300 is out of range 0 or 0.001 .. 1e+06" \
  "$rtusim" render --scene sphere --depth 4 --host-in-bytes-per-cycle 1e-300
expect_error "clock_mhz: 1e-12 is out of range 1 .. 1e+06" \
  "$rtusim" render --scene sphere --depth 4 --clock-mhz 1e-12
expect_error "memory.l1.latency: 2e+06 is out of range 0 .. 1e+06" \
  "$rtusim" render --scene sphere --depth 4 --set memory.l1.latency=2000000
"$rtusim" render --scene sphere --depth 4 --width 8 --height 8 --host-out-bytes-per-cycle 0 \
  --memory cached --dram-bytes-per-cycle 0.001 --clock-mhz 1 >/dev/null || fail "limits refused"

# Negative values for unsigned options are refused, not wrapped.
expect_error "trace-from: must not be negative, got -5" \
  "$rtusim" render --scene sphere --depth 4 --vcd t.vcd --vcd-from -5
expect_error "root: must not be negative, got -1" "$rtusim" jobs --root -1 --out x.bin
expect_error "trace-to: Value 20000000000000 not in range" \
  "$rtusim" render --scene sphere --depth 4 --vcd t.vcd --vcd-to 20000000000000
expect_error "scene.root: -1 is out of range" "$rtusim" build --set scene.root=-1 --out x.svo

# An input is never an output; two outputs are never one file; outputs are checked first.
expect_error "--out 'jobs.bin' is the input --jobs 'jobs.bin'" \
  "$rtusim" golden --svo sphere.svo --jobs jobs.bin --out jobs.bin
cmp -s jobs.bin jobs_copy.bin || fail "the input was overwritten"
expect_error "are one file" "$rtusim" replay --svo sphere.svo --jobs jobs.bin --out r.bin --stats r.bin
expect_error "--out './sphere.svo' is the input --svo 'sphere.svo'" \
  "$rtusim" build --svo sphere.svo --out ./sphere.svo
expect_error "folder 'missing' does not exist" \
  "$rtusim" replay --svo sphere.svo --jobs jobs.bin --out r.bin --stats missing/s.json
[[ ! -e r.bin ]] || fail "replay ran although its --stats could not be written"
expect_error "needs 12 stack frames; 11 are configured" \
  "$rtusim" fps --scene sphere --depth 13 --resolutions 8x8 --cores 1
expect_error "--csv 'missing/f.csv': folder 'missing' does not exist" \
  "$rtusim" fps --svo sphere.svo --resolutions 8x8 --cores 1 --csv missing/f.csv
expect_error "--depth-image 'd.unknownext': no image format" \
  "$rtusim" render --scene sphere --depth 4 --depth-image d.unknownext
mkdir adir
expect_error "--image 'adir' is a directory" "$rtusim" render --scene sphere --depth 4 --image adir

# The golden model refuses what only the timed model uses.
expect_error "--stats, --trace and --timeline need --model ca or lt" \
  "$rtusim" render --model golden --scene sphere --depth 4 --stats s.json
expect_error "cores (command line) has no effect: rtusim render --model golden does not use it" \
  "$rtusim" render --model golden --scene sphere --depth 4 --cores 4
expect_error "cores: 0 is out of range" "$rtusim" render --model golden --cores 0

# Formats over 32 bits get 12-word result records (cli_end_to_end.sh); an invalid format is
# refused before the run, naming it.
expect_error "fraction_bits: 47 is out of range" \
  "$rtusim" golden --svo sphere.svo --jobs jobs.bin --out r.bin --total-bits 48 --fraction-bits 47
expect_error "total_bits: 56 is out of range" \
  "$rtusim" replay --svo sphere.svo --jobs jobs.bin --out r.bin --total-bits 56

# A built image does not start with gigabytes of zeros.
expect_error "--root 4294967295: a built image would start with" \
  "$rtusim" build --scene sphere --depth 3 --root 4294967295 --out x.svo
[[ ! -e x.svo ]] || fail "an image was written"

# Models and trees that would not fit in memory are refused before they are built.
expect_error "the cache tag arrays would need" \
  "$rtusim" render --memory cached --l1-size 1GiB --l1-line 4 --cores 1024 --scene sphere --depth 4
grep -q -- "--l1-size" err.txt || fail "the cache message does not name --l1-size"
# (Whether a tree fits this machine's memory depends on the machine; 32-bit addresses do not.)
start=$SECONDS
expect_error "building menger (depth 14) would take about 70029306103 words, more than 32-bit" \
  "$rtusim" build --scene menger --depth 14 --out x.svo
grep -q -- "lower --depth" err.txt || fail "the build message does not name --depth"
((SECONDS - start < 20)) || fail "refusing the menger build took $((SECONDS - start)) s"

# Trees deeper than the stack: refused before building, naming --stack-frames.
start=$SECONDS
expect_error "--depth 13 builds descriptors down to level 12, which needs 12 stack frames; 11" \
  "$rtusim" render --scene sphere --depth 13
grep -q -- "--stack-frames" err.txt || fail "the stack message does not name --stack-frames"
((SECONDS - start < 5)) || fail "refusing the depth-13 sphere took $((SECONDS - start)) s"

# A chain of 12 descriptors ending in a leaf: depth 13, descriptors down to level 12. Each link
# has one non-leaf child in slot 0 (valid 0x01, pointer 1); the end has a leaf in slot 0.
chain() {  # chain LINKS LAST_WORD_HEX
  for ((i = 0; i < $1; ++i)); do printf '\x00\x01\x01\x00'; done
  printf "$2"
}
chain 12 '\x01\x01\x00\x00' >deep.svo
expect_error "needs 12 stack frames; 11 are configured" \
  "$rtusim" replay --svo deep.svo --jobs jobs.bin --out r.bin
"$rtusim" replay --svo deep.svo --jobs jobs.bin --out r.bin --stack-frames 30 >/dev/null \
  || fail "--stack-frames 30 was not honoured"
"$rtusim" golden --svo deep.svo --jobs jobs.bin --out g.bin --stack-frames 30 >/dev/null \
  || fail "golden with --stack-frames 30"
# The same chain ending in a descriptor without any child: no leaf, but the stack still fills.
chain 12 '\x00\x00\x00\x00' >leafless.svo
expect_error "needs 12 stack frames" "$rtusim" replay --svo leafless.svo --jobs jobs.bin --out r.bin
