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
# A frame of passes (explore/ray_passes.h) streams its runs too, holding the pixels, their hits and
# the passes' rays, not a record or result per ray: 1024x1024 with shadow and two AO rays a hit
# (2.9 million rays) peaks at about 260 MB; it held 1.2 GB (records, results and their copies).
limited "$rtusim" render --model ca --core bvh --scene menger --depth 5 --width 1024 \
  --height 1024 --passes primary,shadow,ao --samples 2 >passes.txt ||
  fail "render --passes of a 1024x1024 frame ran out of 400 MB: $(tail -1 passes.txt)"
grep -q "^frame  .* rays in 3 passes as one run" passes.txt || fail "passes: $(cat passes.txt)"
# What a frame of passes holds is estimated with its rays and refused before any work.
expect_error "(the pixels and hits secondary passes read, their rays), more than the" \
  "$rtusim" render --scene menger --depth 3 --width 16384 --height 16384 --passes primary,ao \
  --samples 1024
# sweep enumerates its grid lazily (config/sweep_points.h): a 400,000-point grid's checks and
# Slurm plan (its dry run), which held 5 GB before (12.8 KB a point), within the limit; the dry
# run names the count and the first and last rows.
limited "$rtusim" sweep --scene sphere --depth 3 --grid "cores=$(seq -s, 1 40)" \
  --grid "width=$(seq -s, 16 115)" --grid "height=$(seq -s, 16 115)" --slurm --dry-run \
  --out grid.csv >grid.txt || fail "a 400,000-point sweep's dry run ran out of 400 MB"
grep -q "rows to run: 400000, the first (0) cores=1 width=16 height=16, the last (399999) \
cores=40 width=115 height=115" grid.txt || fail "dry run of the grid: $(cat grid.txt)"
grep -q '"rows":"0-399999"' grid.slurm/plan.json || fail "the plan's rows"
# EXR and TIFF images stream their rows too (app/row_image.h): a 4096x4096 frame's shaded EXR
# and depth TIFF peak at about 210 MB resident (the depth image's samples, 64 MB, and OpenImageIO's
# libraries, about 140 MB whatever the frame), 470 MB when their rows were held. Measured as a
# peak rather than under the address-space limit, which OpenImageIO's threads cannot start under.
peak_kb=$(python3 - "$rtusim" <<'PY'
import resource, subprocess, sys
subprocess.run([sys.argv[1], "render", "--model", "golden", "--scene", "sphere", "--depth", "3",
                "--width", "4096", "--height", "4096", "--image", "big.exr", "--depth-image",
                "big.tif"], check=True, stdout=subprocess.DEVNULL)
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)
PY
)
((peak_kb < 300000)) || fail "a 4096x4096 frame's EXR and TIFF images peaked at $peak_kb KB"
expect_error "golden ran out of memory while reading SVO image 'big.svo' (629145600 bytes)" \
  limited "$rtusim" golden --svo big.svo --jobs jobs.bin --out out.bin
echo "out of memory: all checks passed"
