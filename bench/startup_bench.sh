#!/usr/bin/env bash
# Start-up cost of the rtusim command: wall time and peak resident set of `rtusim --help` and of
# `rtusim replay` of 64 rays (an 8x8 frame on a depth-5 sphere), over RUNS runs each.
# Usage: bench/startup_bench.sh [path/to/rtusim] [runs]   (default: build/rtusim, 10 runs)
# Figures are recorded in docs/performance.md, section "Start-up".
set -euo pipefail

rtusim=${1:-$(dirname "$0")/../build/rtusim}
runs=${2:-10}
[[ -x $rtusim ]] || { echo "startup_bench: '$rtusim' is not an executable" >&2; exit 1; }
[[ -x /usr/bin/time ]] || { echo "startup_bench: needs GNU time (/usr/bin/time)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$rtusim" build --scene sphere --depth 5 --out "$work/sphere.svo" >/dev/null
"$rtusim" jobs --width 8 --height 8 --out "$work/jobs.bin" >/dev/null

# measure NAME COMMAND...: RUNS runs under GNU time for the maximum resident set, wall time from
# bash's EPOCHREALTIME (GNU time reports only 10 ms steps). Prints the median, min and max wall
# time and the largest maximum resident set.
measure() {
  local name=$1; shift
  local walls=() rss=() start end kib
  for ((i = 0; i < runs; ++i)); do
    start=$EPOCHREALTIME
    /usr/bin/time -f '%M' -o "$work/time" "$@" >/dev/null 2>"$work/stderr" ||
      { echo "startup_bench: '$*' failed:" >&2; cat "$work/stderr" >&2; exit 1; }
    end=$EPOCHREALTIME
    read -r kib <"$work/time"
    walls+=("$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.4f", (b - a) * 1000 }')")
    rss+=("$kib")
  done
  local wall_stats rss_max
  wall_stats=$(printf '%s\n' "${walls[@]}" | sort -g | awk -v n="$runs" '{ w[NR] = $1 }
    END { printf "median %6.1f ms  min %6.1f ms  max %6.1f ms", w[int((n + 1) / 2)], w[1], w[n] }')
  rss_max=$(printf '%s\n' "${rss[@]}" | sort -g | tail -n 1)
  printf '%-7s wall %s  max RSS %.1f MB  (%d runs)\n' "$name" "$wall_stats" \
    "$(awk -v k="$rss_max" 'BEGIN { print k / 1024 }')" "$runs"
}

measure --help "$rtusim" --help
measure replay "$rtusim" replay --svo "$work/sphere.svo" --jobs "$work/jobs.bin" --out "$work/out.bin"

# hyperfine's figures too when it is installed.
if command -v hyperfine >/dev/null; then
  hyperfine --warmup 2 --runs "$runs" -N "$rtusim --help" \
    "$rtusim replay --svo $work/sphere.svo --jobs $work/jobs.bin --out $work/out.bin"
fi
