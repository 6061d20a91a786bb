#!/usr/bin/env bash
# Sampled simulation against the full cycle-accurate run (docs/fidelity.md): per scene, one full
# frame and SEEDS sampled ones; prints the error of the total cycles, how many 95 % intervals cover
# the full value, the host seconds and the fraction of rays simulated.
# Usage: sampled_bench.sh path/to/rtusim [SEEDS] [RESOLUTION] [SCENES...]
#   defaults: 20 seeds, 1920x1080, menger; the cached preset at 16 cores, --sample 0.1
set -euo pipefail
rtusim=$1
seeds=${2:-20}
resolution=${3:-1920x1080}
shift $(( $# < 3 ? $# : 3 ))
scenes=("${@:-menger}")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
common=(--preset cached --depth 8 --cores 16 --resolutions "$resolution" -j 1)

for scene in "${scenes[@]}"; do
  "$rtusim" fps "${common[@]}" --scene "$scene" --csv "$work/$scene-full.csv" >/dev/null
  for seed in $(seq 1 "$seeds"); do
    "$rtusim" fps "${common[@]}" --scene "$scene" --sample 0.1 --sample-seed "$seed" \
      --csv "$work/$scene-$seed.csv" >/dev/null
  done
done

/usr/bin/python3 - "$work" "$seeds" "${scenes[@]}" <<'PY'
import csv, statistics, sys
work, seeds, scenes = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
def row(path):
    with open(path) as f:
        return next(csv.DictReader(f))
print("| scene | full cycles | full s | sampled s (mean) | speed-up | rays simulated | "
      "mean abs error | max abs error | 95 % intervals covering |")
print("|---|---|---|---|---|---|---|---|---|")
for scene in scenes:
    full = row(f"{work}/{scene}-full.csv")
    exact = float(full["total_cycles"])
    runs = [row(f"{work}/{scene}-{s}.csv") for s in range(1, seeds + 1)]
    errors = [abs(float(r["total_cycles"]) / exact - 1) for r in runs]
    covered = sum(float(r["total_cycles_ci_low"]) <= exact <= float(r["total_cycles_ci_high"])
                  for r in runs)
    seconds = statistics.mean(float(r["host_seconds"]) for r in runs)
    print(f"| {scene} | {int(exact)} | {float(full['host_seconds']):.2f} | {seconds:.2f} | "
          f"{float(full['host_seconds']) / seconds:.1f}x | "
          f"{float(runs[0]['simulated_fraction']) * 100:.1f} % | "
          f"{statistics.mean(errors) * 100:.2f} % | {max(errors) * 100:.2f} % | "
          f"{covered} of {seeds} |")
PY
