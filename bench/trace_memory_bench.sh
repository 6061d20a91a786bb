#!/usr/bin/env bash
# Memory of a full trace: `rtusim replay` of one frame (default 1920x1080) on a depth-8 sphere at
# 16 cores with cached memory, untraced and with every signal traced (--vcd), wall time and peak
# resident set of each. The trace goes through a pipe to a byte count, not to the disk.
# Usage: bench/trace_memory_bench.sh [path/to/rtusim] [width] [height]
# Figures are recorded in docs/performance.md, section "Trace memory".
set -euo pipefail

rtusim=${1:-$(dirname "$0")/../build/rtusim}
width=${2:-1920}
height=${3:-1080}
[[ -x $rtusim ]] || { echo "trace_memory_bench: '$rtusim' is not an executable" >&2; exit 1; }
[[ -x /usr/bin/time ]] || { echo "trace_memory_bench: needs GNU time (/usr/bin/time)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$rtusim" build --scene sphere --depth 8 --out "$work/sphere.svo" >/dev/null
"$rtusim" jobs --width "$width" --height "$height" --out "$work/jobs.bin" >/dev/null
replay=("$rtusim" replay --svo "$work/sphere.svo" --jobs "$work/jobs.bin" --out "$work/out.bin"
        --cores 16 --memory cached)

# run NAME COMMAND...: prints wall seconds and peak resident MB.
run() {
  local name=$1; shift
  /usr/bin/time -f '%e %M' -o "$work/time" "$@" >/dev/null
  read -r seconds kib <"$work/time"
  printf '%-10s %8.1f s %8.1f MB resident' "$name" "$seconds" \
    "$(awk -v k="$kib" 'BEGIN { print k / 1024 }')"
}

echo "${width}x${height}, $((width * height)) rays, 16 cores, cached memory"
run untraced "${replay[@]}"
echo
# A full trace is far above the default --trace-max-mb: lift it. Should rtusim fail before it
# opens the pipe, opening it here lets the byte count end instead of waiting for a writer.
mkfifo "$work/trace.vcd"
wc -c <"$work/trace.vcd" >"$work/bytes" &
run traced "${replay[@]}" --vcd "$work/trace.vcd" --trace-max-mb 1000000 || : >"$work/trace.vcd"
wait
echo "$(awk -v b="$(<"$work/bytes")" 'BEGIN { printf "   VCD %.0f MB", b / 1e6 }')"
run "traced FST" "${replay[@]}" --trace "$work/trace.fst" --trace-max-mb 1000000
echo "$(awk -v b="$(stat -c %s "$work/trace.fst")" 'BEGIN { printf "   FST %.0f MB", b / 1e6 }')"
