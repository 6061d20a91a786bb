#!/usr/bin/env bash
# Issue 33: render's images are written as the frame's results leave the run (FrameImageWriter:
# a PNG file row by row as its rows complete; docs/robustness.md, "Memory"). The cycle-accurate
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
[[ -z $(compgen -G '.*.part-*' || true) ]] || fail "temporary files left: $(compgen -G '.*.part-*')"
echo "streamed images: the same files on golden, ca and lt"
