#!/usr/bin/env bash
# The SystemC model's VCD traces, normalised to "cycle signal value" lines, equal the traces
# recorded in tests/data/vcd before the channel protocol was rewritten (issue 9): every level
# of every channel, core state, stack depth and cache counter, in every cycle. The traces were
# recorded from the per-cycle handshake model, which the equivalence tests tie to the thesis RTL.
# Usage: vcd_recorded.sh path/to/rtusim [--record]   (--record rewrites the stored traces)
set -euo pipefail
rtusim=$1
record=${2:-}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
data=$here/data/vcd
source "$here/shell_test_helpers.sh"
python=/usr/bin/python3
[[ -x $python ]] || python=python3

"$rtusim" build --scene sphere --depth 5 --out sphere.svo >/dev/null
"$rtusim" jobs --width 16 --height 12 --out jobs.bin >/dev/null
header=$("$rtusim" build --scene sphere --depth 5 --model-header --out model.svo |
  sed -n 's/^model header at word //p')
"$rtusim" jobs --width 12 --height 8 --rays rays.bin --model-address "$header" >/dev/null

# name: replay options
configurations=(
  "ideal_1:--cores 1"
  "ideal_4:--cores 4"
  "ideal_16:--cores 16"
  "cached_1:--cores 1 --memory cached"
  "cached_4:--cores 4 --memory cached"
  "cached_16:--cores 16 --memory cached"
  "rr_4_cached:--cores 4 --scheduler rr --memory cached"
  "fa_4_cached:--cores 4 --scheduler fa --memory cached"
  "paced_reorder_2:--cores 2 --host-in-bytes-per-cycle 3 --host-out-bytes-per-cycle 8 --reorder 4"
  "paced_4_cached:--cores 4 --memory cached --host-in-bytes-per-cycle 8 --host-out-bytes-per-cycle 8"
  "rays_4:--cores 4 --rays-input"
)

failed=0
for entry in "${configurations[@]}"; do
  name=${entry%%:*}
  read -r -a options <<<"${entry#*:}"
  input=(--svo sphere.svo --jobs jobs.bin)
  if [[ ${options[-1]} == --rays-input ]]; then
    unset 'options[-1]'
    input=(--svo model.svo --rays rays.bin)
  fi
  # The recorded traces predate the ray ids (signal class ids): every other class.
  "$rtusim" replay "${input[@]}" "${options[@]}" --out "$name.bin" \
    --vcd "$name.vcd" --trace-signals handshakes,states,stack,caches >/dev/null
  "$python" "$here/vcd_normalise.py" "$name.vcd" 10000 >"$name.txt"
  if [[ $record == --record ]]; then
    gzip -9n <"$name.txt" >"$data/$name.txt.gz"
  elif ! diff <(gzip -dc "$data/$name.txt.gz") "$name.txt" >"$name.diff"; then
    echo "FAIL: $name: the trace differs from the recorded one; first differences:"
    head -8 "$name.diff"
    failed=1
  fi
done
(( failed == 0 )) || exit 1
echo "VCD traces equal the recorded ones: ${#configurations[@]} configurations"
