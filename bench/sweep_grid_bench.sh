#!/usr/bin/env bash
# Peak resident memory and wall time of a sweep's dry run (`sweep --slurm --dry-run`: every point
# checked, the Slurm plan written) against the grid's size (issue 33, "Memory bounded by the
# work"): 10^4 .. 10^7 points over cores, width, height and clock_mhz. The grid is enumerated
# lazily (src/config/sweep_points.h), so the peak stays flat; the time is the checks, a few µs a
# point (docs/robustness.md, "Sweep grids, enumerated lazily").
# Usage: bench/sweep_grid_bench.sh [path/to/rtusim] [exponents...]   (default 4 5 6 7)
# Figures are recorded in docs/performance.md, section "Sweep grids".
set -euo pipefail

rtusim=${1:-$(dirname "$0")/../build/rtusim}
shift || true
exponents=("$@")
((${#exponents[@]})) || exponents=(4 5 6 7)
[[ -x $rtusim ]] || { echo "sweep_grid_bench: '$rtusim' is not an executable" >&2; exit 1; }
[[ -x /usr/bin/time ]] || { echo "sweep_grid_bench: needs GNU time (/usr/bin/time)" >&2; exit 1; }
rtusim=$(cd "$(dirname "$rtusim")" && pwd)/$(basename "$rtusim")

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

values() { seq -s, "$1" $(($1 + $2 - 1)); }  # values FIRST COUNT
printf '%-8s %12s %10s\n' points peak_MB wall_s
for exponent in "${exponents[@]}"; do
  # 100 values a key for the first keys, 10^(exponent mod 2) for the last.
  grid=()
  keys=(cores width height clock_mhz)
  firsts=(1 16 16 100)
  left=$exponent
  for k in 0 1 2 3; do
    ((left > 0)) || break
    count=$((left >= 2 ? 100 : 10))
    grid+=(--grid "${keys[$k]}=$(values "${firsts[$k]}" "$count")")
    left=$((left - (left >= 2 ? 2 : 1)))
  done
  rm -rf grid.csv grid.slurm
  /usr/bin/time -f '%M %e' -o time "$rtusim" sweep --scene sphere --depth 5 "${grid[@]}" \
    --slurm --dry-run --out grid.csv >/dev/null
  read -r kib seconds <time
  printf '10^%-6s %12.1f %10s\n' "$exponent" "$(echo "$kib / 1024" | bc -l)" "$seconds"
done
