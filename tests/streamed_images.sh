#!/usr/bin/env bash
# Issue 33: render's images are written as the frame's results leave the run (FrameImageWriter:
# a PNG, EXR or TIFF file row by row as its rows complete; docs/robustness.md, "Memory"). The cycle-accurate
# and loosely-timed models hand their results over out of job order, the golden model in order:
# the images of one frame are the same files on every model (each also checked byte for byte
# against the images of the whole frame before the change: docs/robustness.md).
# Usage: streamed_images.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"

frame=(--width 160 --height 120)
for model in golden ca lt; do
  "$rtusim" render --model "$model" "${frame[@]}" --image "$model.png" \
    --depth-image "${model}_depth.png" --cost-image "${model}_cost.png" >/dev/null
done
for image in "" _depth _cost; do
  [[ -s golden$image.png ]] || fail "no golden$image.png"
  for model in ca lt; do
    cmp -s "golden$image.png" "$model$image.png" || fail "$model$image.png differs from golden's"
  done
done
# EXR and TIFF rows go through OpenImageIO's scanline writes into the file (their writers seek
# back): the same images on every model, but for the time stamp their headers carry (checked byte
# for byte against the files written whole before the change: docs/robustness.md).
same_but_date() {
  python3 - "$1" "$2" <<'PY'
import re, sys
stamp = re.compile(rb"\d{4}:\d\d:\d\d \d\d:\d\d:\d\d")
a, b = (stamp.sub(b"DATE", open(path, "rb").read()) for path in sys.argv[1:])
sys.exit(0 if a == b else 1)
PY
}
for format in exr tif; do
  for model in golden ca; do
    "$rtusim" render --model "$model" --width 96 --height 72 --image "$model.$format" \
      --depth-image "${model}_depth.$format" --cost-image "${model}_cost.$format" >/dev/null
  done
  for image in "" _depth _cost; do
    [[ -s golden$image.$format ]] || fail "no golden$image.$format"
    same_but_date "golden$image.$format" "ca$image.$format" ||
      fail "ca$image.$format differs from golden's"
  done
done
[[ -z $(compgen -G '.*.part-*' || true) ]] || fail "temporary files left: $(compgen -G '.*.part-*')"
echo "streamed images: the same files on golden, ca and lt (PNG), golden and ca (EXR, TIFF)"
