#!/usr/bin/env bash
# Issue 33, section 1: an output is never a truncated file that looks complete, and never
# removes a path the program did not create. Every output on a full disk (a filled 64 KiB tmpfs
# in a private mount namespace, skipped where unshare cannot make one) fails, naming the file and
# the cause, and leaves no file; a symbolic link to /dev/full survives a failed write; errors on
# standard output exit non-zero. Usage: output_faults.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"

"$rtusim" build --scene sphere --depth 6 --out sphere.svo >/dev/null
"$rtusim" jobs --width 32 --height 24 --out jobs.bin >/dev/null
frame=(--svo sphere.svo --width 32 --height 24)

# A link to /dev/full as the output: written in place, the error names it, nothing is removed.
ln -s /dev/full full.bin
for command in "golden --svo sphere.svo --jobs jobs.bin --out" \
  "replay --svo sphere.svo --jobs jobs.bin --out" "jobs --width 32 --height 24 --out"; do
  # shellcheck disable=SC2086
  expect_error "cannot write 'full.bin': No space left on device" "$rtusim" $command full.bin
  [[ -L full.bin && -c /dev/full ]] || fail "$command removed full.bin or /dev/full"
done
ln -s /dev/full full.png
expect_error "cannot write 'full.png': No space left" "$rtusim" render "${frame[@]}" \
  --image full.png
[[ -L full.png && -c /dev/full ]] || fail "render removed full.png or /dev/full"

# An output named by a descriptor (/dev/stdout, here a pipe) is written in place.
"$rtusim" golden --svo sphere.svo --jobs jobs.bin --results-csv /dev/stdout | cat >piped.txt
grep -q '^id,hit,t' piped.txt || fail "results CSV to /dev/stdout"

# Standard output.
if "$rtusim" config --dump >/dev/full 2>err.txt; then fail "config --dump > /dev/full succeeded"; fi
grep -q "cannot write standard output" err.txt || fail "$(cat err.txt)"

if ! unshare -rm true 2>/dev/null; then
  echo "no private mount namespace: the full-disk cases are skipped"
  exit 0
fi
mkdir disk
# on_full_disk FILE command...: runs the command with the folder disk/ a full file system, and
# expects it to fail naming disk/FILE and leave nothing but the filler there.
on_full_disk() {
  local file=$1; shift
  # shellcheck disable=SC2016
  if unshare -rm bash -c 'mount -t tmpfs -o size=64k rtusim-full disk && \
      { cat /dev/zero >disk/filler 2>/dev/null || true; } && \
      { status=0; "$@" || status=$?; ls -A disk >listing.txt; exit $status; }' \
      bash "$@" >out.txt 2>err.txt; then
    fail "'$*' succeeded on a full disk"
  fi
  grep -q "cannot write 'disk/$file': No space left on device" err.txt ||
    fail "'$*' did not name disk/$file: $(cat err.txt)"
  [[ $(cat listing.txt) == filler ]] || fail "'$*' left $(cat listing.txt) on the full disk"
}
on_full_disk jobs.bin "$rtusim" jobs --width 32 --height 24 --out disk/jobs.bin
on_full_disk out.bin "$rtusim" golden --svo sphere.svo --jobs jobs.bin --out disk/out.bin
on_full_disk results.csv "$rtusim" golden --svo sphere.svo --jobs jobs.bin \
  --results-csv disk/results.csv
on_full_disk image.png "$rtusim" render "${frame[@]}" --image disk/image.png
on_full_disk cost.png "$rtusim" render "${frame[@]}" --cost-image disk/cost.png
on_full_disk depth.exr "$rtusim" render "${frame[@]}" --depth-image disk/depth.exr
on_full_disk stats.json "$rtusim" render "${frame[@]}" --stats disk/stats.json
on_full_disk trace.fst "$rtusim" render "${frame[@]}" --trace disk/trace.fst
on_full_disk trace.vcd "$rtusim" render "${frame[@]}" --trace disk/trace.vcd
on_full_disk timeline.json "$rtusim" render "${frame[@]}" --timeline disk/timeline.json
on_full_disk fps.csv "$rtusim" fps --svo sphere.svo --resolutions 32x24 --cores 1 --csv disk/fps.csv
on_full_disk precision.csv "$rtusim" precision "${frame[@]}" --formats Q16.16 \
  --csv disk/precision.csv
on_full_disk sphere.svo "$rtusim" build --scene sphere --depth 6 --out disk/sphere.svo
echo "output faults: all checks passed"
