#!/usr/bin/env bash
# Warm frames (issue 31 section 2): `--warm-frames N` starts the measured frame from the caches N
# frames of the same rays leave (functional warming). Checked against the frame simulated back to
# back: a job buffer holding the frame twice, run in one simulation, spends on its second frame
# what the cold frame and the warmed frame differ by, within 2 %. Every report says how the
# caches started; the loosely-timed model, which starts cold, refuses warm frames; with ideal
# memory the setting is warned as having no effect.
# Usage: warm_frames.sh path/to/rtusim
set -euo pipefail
rtusim=$1
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$here/shell_test_helpers.sh"

"$rtusim" build --scene menger --depth 5 --out menger.svo >/dev/null
"$rtusim" jobs --width 96 --height 64 --out one.bin >/dev/null
cat one.bin one.bin >two.bin
run=(--preset asic --svo menger.svo --out out.bin --cores 8)
cycles() { sed -n 's/^rays [0-9]*, total cycles \([0-9]*\) .*/\1/p' "$1"; }
"$rtusim" replay "${run[@]}" --jobs one.bin >cold.txt
"$rtusim" replay "${run[@]}" --jobs two.bin >two.txt
"$rtusim" replay "${run[@]}" --jobs one.bin --warm-frames 1 --stats warm.json >warm.txt
cold=$(cycles cold.txt) two=$(cycles two.txt) warm=$(cycles warm.txt)
python3 - "$cold" "$two" "$warm" <<'PY' || fail "warm frame against back to back: cold $cold, two $two, warm $warm"
import sys
cold, two, warm = map(int, sys.argv[1:])
second = two - cold  # the second frame of two back to back
assert warm < cold, (warm, cold)
assert abs(warm - second) <= 0.02 * second, (warm, second)
PY
grep -q "caches cold$" cold.txt || fail "the cold report does not say so"
grep -q "caches warm after 1 frame$" warm.txt || fail "the warm report does not say so"
grep -q '"caches": "warm after 1 frame"' warm.json || fail "the statistics JSON lacks memory.caches"
# More warm frames change nothing once the caches hold the frame's lines.
"$rtusim" replay "${run[@]}" --jobs one.bin --warm-frames 3 >warm3.txt
[[ $(cycles warm3.txt) -le $warm ]] || fail "three warm frames slower than one"

expect_error "warm_frames needs --model ca" "$rtusim" replay "${run[@]}" --jobs one.bin \
  --warm-frames 1 --model lt
"$rtusim" replay --svo menger.svo --jobs one.bin --out out.bin --warm-frames 1 >ideal.txt 2>ideal.err
grep -q "warm_frames.*has no effect.*memory.kind is ideal" ideal.err || fail "no warning with ideal memory: $(cat ideal.err)"
"$rtusim" fps "${run[@]:0:4}" --set jobs=one.bin --cores 8 --warm-frames 1 >fps.txt
grep -q "cached memory (caches warm after 1 frame)" fps.txt || fail "fps heading: $(head -1 fps.txt)"
grep -q "^one.bin *8 *6144 *$warm " fps.txt || fail "fps row differs from replay's warm frame: $(cat fps.txt)"
# fidelity with warm frames: the loosely-timed modes (cold only) are skipped with a note, unless
# asked for; the cycle-accurate rows start warm.
"$rtusim" fidelity "${run[@]:0:4}" --set jobs=one.bin --cores 8 --warm-frames 1 \
  >fidelity.txt 2>&1 || fail "fidelity with warm frames: $(cat fidelity.txt)"
grep -q "^note: the loosely-timed modes are skipped" fidelity.txt || fail "no note: $(cat fidelity.txt)"
grep -q "^systemc .* $warm " fidelity.txt || fail "fidelity's SystemC row is not the warm frame: $(cat fidelity.txt)"
expect_error "the loosely-timed model does not apply" "$rtusim" fidelity "${run[@]:0:4}" \
  --set jobs=one.bin --warm-frames 1 --quanta 100
echo "warm frames: ok"
