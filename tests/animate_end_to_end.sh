#!/usr/bin/env bash
# rtusim animate (issue 14) from the command line: frames, CSV, plot and the cache on the
# procedural example scene; the same frames on the cycle-accurate model with its simulated cycles,
# in one worker process and in two; the loosely-timed model refused; a malformed scene file named
# with its key before any model is built. Usage: animate_end_to_end.sh path/to/rtusim path/to/scenes
set -euo pipefail
rtusim=$1
scenes=$(cd "$2" && pwd)
source "$(dirname "${BASH_SOURCE[0]}")/shell_test_helpers.sh"

"$rtusim" animate --scene-file "$scenes/procedural.toml" --frames 3 --width 48 --height 27 \
  --out-dir out --cache-dir cache --threads 2 >first.txt
grep -q "built" first.txt || fail "the first run did not build its models"
for file in out/frame_0000.png out/frame_0002.png out/frames.csv; do
  [[ -s $file ]] || fail "$file missing"
done
[[ $(wc -l <out/frames.csv) -eq 4 ]] || fail "frames.csv should hold a header and 3 frames"
head -1 out/frames.csv | grep -q "^frame,time_s,pixels,rays_traced,rays_saved" || fail "CSV header"
# The camera of the procedural scene holds still: frames after the first reuse pixels.
saved=$(awk -F, 'NR == 3 { print $5 }' out/frames.csv)
(( saved > 0 )) || fail "the hit buffer saved no ray in frame 1"

"$rtusim" animate --scene-file "$scenes/procedural.toml" --frames 1 --width 48 --height 27 \
  --out-dir out2 --cache-dir cache >second.txt
grep -q "from the cache" second.txt || fail "the second run rebuilt its models"

# The cycle-accurate and the loosely-timed models: the golden frames, with cycles of their own
# for traced rays (the SystemC run's and the loosely-timed RTU's, not the recurrence's).
for model in ca lt; do
  "$rtusim" animate --scene-file "$scenes/procedural.toml" --frames 3 --width 48 --height 27 \
    --out-dir out_$model --cache-dir cache --model $model --cores 4 >$model.txt
  grep -q "($model model)" $model.txt || fail "the $model run did not say its model"
  for frame in 0000 0002; do
    cmp -s out/frame_$frame.png out_$model/frame_$frame.png || fail "$model frame $frame differs from golden"
  done
  awk -F, 'NR > 1 && $4 > 0 && $13 == 0 { exit 1 }' out_$model/frames.csv || fail "$model frame without cycles"
done
# Frames in two forked workers: the same rows (but the host seconds) and the same images as in
# one. With two workers each of the 4 frames is a range of its own: frames 1 to 3 prime their hit
# buffer with the frame before, and save rays.
for jobs in 1 2; do
  "$rtusim" animate --scene-file "$scenes/procedural.toml" --frames 4 --width 48 --height 27 \
    --out-dir out_j$jobs --cache-dir cache --model ca --cores 4 -j $jobs >j$jobs.txt
  cut -d, -f1-15 out_j$jobs/frames.csv >rows_j$jobs.csv
done
[[ $(wc -l <rows_j2.csv) -eq 5 ]] || fail "the 2-worker run should write a header and 4 frames"
cmp -s rows_j1.csv rows_j2.csv || fail "2 workers wrote other CSV rows than 1: $(diff rows_j1.csv rows_j2.csv)"
for frame in 0000 0001 0002 0003; do
  cmp -s out_j1/frame_$frame.png out_j2/frame_$frame.png || fail "frame $frame differs with 2 workers"
done
awk -F, 'NR > 2 && $5 == 0 { exit 1 }' rows_j2.csv || fail "a primed frame saved no ray"
expect_error "--workers: Value 0 not in range" \
  "$rtusim" animate --scene-file "$scenes/procedural.toml" -j 0 --out-dir out5

expect_error "--model lt does not apply: results pass a reorder buffer" \
  "$rtusim" animate --scene-file "$scenes/procedural.toml" --model lt --reorder 8 --out-dir out3
expect_error "does not model paced host links" \
  "$rtusim" animate --scene-file "$scenes/procedural.toml" --model lt --preset cached --out-dir out3

sed 's/translation = \[0, -1.3, 0\]/translaton = [0, -1.3, 0]/' \
  "$scenes/procedural.toml" >bad.toml
expect_error "bad.toml', line 25: key 'instances\[0\].keys\[0\].translaton': unknown key" \
  "$rtusim" animate --scene-file bad.toml --out-dir out4 --cache-dir cache
[[ ! -e out4/frame_0000.png ]] || fail "frames written for a malformed scene file"
echo "animate end to end: ok"
