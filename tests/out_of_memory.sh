#!/usr/bin/env bash
# An allocation that fails names the command and what it was doing, not a bare std::bad_alloc
# (issue 33). The address space is limited to 400 MB so that large inputs run out quickly.
# Usage: out_of_memory.sh path/to/rtusim
set -euo pipefail
rtusim=$1
source "$(dirname "${BASH_SOURCE[0]}")/shell_test_helpers.sh"

"$rtusim" jobs --width 8 --height 8 --out jobs.bin >/dev/null
truncate -s 600M big.svo
limited() { (ulimit -v 400000 && "$@"); }
expect_error "jobs ran out of memory while making the rays of a 16384x16384 frame (std::bad_alloc)" \
  limited "$rtusim" jobs --width 16384 --height 16384 --out frame.bin
# render streams its rays (docs/robustness.md, "Memory"): a 4096x4096 frame, which took 4 GB
# before, renders within the limit on the golden and the cycle-accurate model.
for model in golden ca; do
  limited "$rtusim" render --model "$model" --scene sphere --depth 3 --width 4096 --height 4096 \
    >/dev/null || fail "render --model $model of a 4096x4096 frame ran out of 400 MB"
done
expect_error "golden ran out of memory while reading SVO image 'big.svo' (629145600 bytes)" \
  limited "$rtusim" golden --svo big.svo --jobs jobs.bin --out out.bin
echo "out of memory: all checks passed"
