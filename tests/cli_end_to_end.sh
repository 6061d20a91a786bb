#!/usr/bin/env bash
# End-to-end use of the rtusim command: build, validate, jobs, golden, render, and clear errors
# with a non-zero exit for malformed inputs. Usage: cli_end_to_end.sh path/to/rtusim
set -euo pipefail
rtusim=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

fail() { echo "FAIL: $*" >&2; exit 1; }
expect_error() {  # expect_error "message part" command...
  local message=$1; shift
  if "$@" >out.txt 2>err.txt; then fail "'$*' succeeded"; fi
  grep -q -- "$message" err.txt || { cat err.txt >&2; fail "'$*' did not say '$message'"; }
}

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
[[ -s img.png && -s d.exr && -s c.png ]] || fail "images missing"

printf 'garbage' >bad.svo
expect_error "not a multiple" "$rtusim" validate bad.svo
printf '\x01\x00\x00\x00' >leaf_not_valid.svo  # valid=0, leaf=1 in slot 0
expect_error "slot 0" "$rtusim" validate leaf_not_valid.svo
head -c 100 jobs.bin >short.bin
expect_error "not a multiple" "$rtusim" golden --svo sphere.svo --jobs short.bin --out x.bin
expect_error "unknown procedural scene" "$rtusim" build --scene nope --out x.svo
expect_error "one scene" "$rtusim" render --svo sphere.svo --mesh jobs.bin
expect_error "three numbers" "$rtusim" render --camera 1,2
expect_error "fraction bits" "$rtusim" golden --svo sphere.svo --jobs jobs.bin --out x.bin \
  --fraction-bits 40
expect_error "image size" "$rtusim" jobs --width 0 --out x.bin
echo "cli end-to-end: ok"
