#!/usr/bin/env bash
# The cost of incoherence (issue 32, docs/workloads.md "First measurements"): one camera frame's
# primary rays and the shadow, AO, reflected, diffuse and random rays spawned from it, each replayed
# alone on the cycle-accurate model with the cached preset, in pixel order (and shuffled). Prints
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
echo "| workload | order | rays | hits | cycles/ray | cost/ray | blocked/ray | L1 hit | L2 hit | DRAM B/ray | DRAM util | limit |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
for order in pixel shuffled; do
  for type in primary shadow ao reflection diffuse random; do
    extra=()
    [[ $type == ao ]] && extra=(--samples 4)
    "$rtusim" jobs --svo "$work/m.svo" --model-address "$header" --ray-type "$type" \
      --order "$order" --rays "$work/$type.bin" "${frame[@]}" "${extra[@]}" >/dev/null
    "$rtusim" replay --preset "$preset" --svo "$work/m.svo" --rays "$work/$type.bin" \
      --out "$work/out.bin" --stats "$work/$type.json" >/dev/null
    python3 - "$work/$type.json" "$type" "$order" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
st = s.get("statistics", s)
rays = st["rays"]
l1 = [c["l1"] for c in st["cores"] if "l1" in c]
def rate(hits, accesses):
    return hits / accesses if accesses else 0.0
l1hits = sum(c.get("hits", 0) for c in l1)
l1acc = sum(c.get("accesses", 0) for c in l1)
l2 = st.get("l2", {})
dram = l2.get("dram_bytes", l2.get("bytes_from_dram", 0))
print(f"| {sys.argv[2]} | {sys.argv[3]} | {rays} | {st.get('hits', '')} | {st['cycles_per_ray']:.2f} "
      f"| {st['cost']['mean']:.2f} | {st['blocked_cycles']['mean']:.2f} | {rate(l1hits, l1acc):.3f} "
      f"| {rate(l2.get('hits', 0), l2.get('accesses', 0)):.3f} | {dram / rays if rays else 0:.1f} "
      f"| {st['utilisation']['dram_bandwidth']:.3f} | {st['limit'] or 'none'} |")
PY
  done
done
