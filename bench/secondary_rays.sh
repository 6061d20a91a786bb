#!/usr/bin/env bash
# The cost of incoherence (issue 32, docs/workloads.md "First measurements"): one camera frame's
# primary rays and the shadow, AO, reflected, diffuse and random rays spawned from it, each replayed
# alone on the cycle-accurate model with the cached preset, in each order (pixel, shuffled, sorted). Prints
# one markdown row per workload: rays, hits, cycles per ray, cost and blocked cycles per ray, L1
# and L2 hit rates, DRAM bytes per ray, DRAM utilisation and the limit.
# Usage: bench/secondary_rays.sh [rtusim] [scene] [depth] [width] [height] [preset]
set -euo pipefail

rtusim=${1:-$(dirname "$0")/../build/rtusim}
scene=${2:-menger}
depth=${3:-8}
width=${4:-160}
height=${5:-90}
preset=${6:-cached}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

header=$("$rtusim" build --scene "$scene" --depth "$depth" --out "$work/m.svo" --model-header |
  sed -n 's/.*model header at word \([0-9]*\).*/\1/p')
frame=(--width "$width" --height "$height")
echo "| workload | order | rays | hit rate | cycles/ray | cost/ray | blocked/ray | L1 hit | L2 hit | DRAM B/ray | DRAM util | limit |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
for order in pixel shuffled sorted; do
  for type in primary shadow ao reflection diffuse random; do
    extra=()
    [[ $type == ao ]] && extra=(--samples 4)
    "$rtusim" jobs --svo "$work/m.svo" --model-address "$header" --ray-type "$type" \
      --order "$order" --rays "$work/$type.bin" "${frame[@]}" "${extra[@]}" >/dev/null
    "$rtusim" replay --preset "$preset" --svo "$work/m.svo" --rays "$work/$type.bin" \
      --out "$work/out.bin" --stats "$work/$type.json" >/dev/null
    python3 - "$work/$type.json" "$work/out.bin" "$type" "$order" <<'PY'
import json, struct, sys
st = json.load(open(sys.argv[1]))["statistics"]
data = open(sys.argv[2], "rb").read()
words = struct.unpack("<%dI" % (len(data) // 4), data)
hits = sum(words[i + 1] for i in range(0, len(words), 8))
rays, memory = st["rays"], st["memory"]
print(f"| {sys.argv[3]} | {sys.argv[4]} | {rays} | {hits / rays:.3f} | {st['cycles_per_ray']:.2f} "
      f"| {st['cost']['mean']:.2f} | {st['blocked_cycles']['mean']:.2f} "
      f"| {memory['l1']['hit_rate']:.3f} | {memory['l2']['hit_rate']:.3f} "
      f"| {memory['dram']['bytes'] / rays:.1f} | {st['utilisation']['dram_bandwidth']:.3f} "
      f"| {st['limit']} |")
PY
  done
done
