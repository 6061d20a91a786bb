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
expect_error "unknown procedural scene" "$rtusim" build --scene nope --out x.svo
expect_error "one scene" "$rtusim" render --svo sphere.svo --mesh jobs.bin
expect_error "three numbers" "$rtusim" render --camera 1,2
expect_error "fraction bits" "$rtusim" golden --svo sphere.svo --jobs jobs.bin --out x.bin \
  --fraction-bits 40
expect_error "image size" "$rtusim" jobs --width 0 --out x.bin
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
echo "cli end-to-end: ok"
