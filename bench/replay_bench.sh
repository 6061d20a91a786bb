#!/usr/bin/env bash
# The whole `rtusim replay` process on issue 9's frame: 1280x720 primary rays on menger at depth 6,
# 16 cores, ideal memory (Verilator on the thesis RTL: about 2.6 s, so 8x is 0.325 s). Wall time
# from bash's clock; CPU seconds, maximum resident set and page faults from GNU time. With several
# binaries (say, before and after a change) the runs alternate, so a machine whose load drifts
# treats them alike.
# Usage: bench/replay_bench.sh [runs] [rtusim ...]   (default: 10 runs of build/rtusim)
# Figures are recorded in docs/performance.md, section "Issue 9's targets".
set -euo pipefail

runs=${1:-10}
shift || true
binaries=("$@")
((${#binaries[@]})) || binaries=("$(dirname "$0")/../build/rtusim")
for rtusim in "${binaries[@]}"; do
  [[ -x $rtusim ]] || { echo "replay_bench: '$rtusim' is not an executable" >&2; exit 1; }
done
[[ -x /usr/bin/time ]] || { echo "replay_bench: needs GNU time (/usr/bin/time)" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"${binaries[0]}" build --scene menger --depth 6 --out "$work/menger.svo" >/dev/null
"${binaries[0]}" jobs --width 1280 --height 720 --out "$work/jobs.bin" >/dev/null

# One line per run: binary index, wall ms, user + system s, max RSS KiB, minor page faults.
for ((i = 0; i < runs; ++i)); do
  for b in "${!binaries[@]}"; do
    start=$EPOCHREALTIME
    /usr/bin/time -f '%U %S %M %R' -o "$work/time" "${binaries[$b]}" replay \
      --svo "$work/menger.svo" --jobs "$work/jobs.bin" --out "$work/out.bin" >/dev/null
    end=$EPOCHREALTIME
    read -r user system rss faults <"$work/time"
    awk -v b="$b" -v s="$start" -v e="$end" -v u="$user" -v y="$system" -v r="$rss" -v f="$faults" \
      'BEGIN { printf "%d %.1f %.2f %d %d\n", b, (e - s) * 1000, u + y, r, f }' >>"$work/runs"
  done
done

# median COLUMN: the median of that column of the binary's runs (file on standard input).
median() { sort -g -k"$1" | awk -v c="$1" '{ v[NR] = $c } END { print v[int((NR + 1) / 2)] }'; }

for b in "${!binaries[@]}"; do
  awk -v b="$b" '$1 == b' "$work/runs" >"$work/mine"
  wall=$(median 2 <"$work/mine")
  cpu=$(median 3 <"$work/mine")
  awk -v name="${binaries[$b]}" -v wall="$wall" -v cpu="$cpu" '
    NR == 1 || $2 < low { low = $2 }
    NR == 1 || $2 > high { high = $2 }
    $4 > rss { rss = $4 }
    { faults = $5 }
    END {
      printf "%s\n  wall median %.0f ms (min %.0f, max %.0f)  cpu median %.2f s  max RSS %.0f MB" \
             "  page faults %d  (%d runs)\n", name, wall, low, high, cpu, rss / 1024, faults, NR
    }' "$work/mine"
done
