#!/usr/bin/env bash
# A frame's passes on every core kind (issue 32, docs/workloads.md "Every kind's own passes"):
# `render --passes primary,shadow,ao,diffuse` on the SVO core and on the BVH, BIH and k-d cores
# built over the same scene's voxel faces, each kind's secondary rays spawned from its own golden
# hits and run with the primary rays as one workload (the cycle-accurate model, the preset's
# memory, cold caches), the secondary rays in pixel order and shuffled (a wavefront renderer's
# mixing: the cost of incoherence). Prints one markdown row per kind, order and pass: rays, hit
# rate, cycles per ray, cost per ray, DRAM bytes per ray, DRAM utilisation and the limit of the
# pass's window of the frame's run, and one row for the whole frame.
# Usage: bench/frame_passes.sh [rtusim] [scene] [depth] [width] [height] [preset] [samples] [kinds]
#        [render options, e.g. "--kd-matrix normal"]
set -euo pipefail

rtusim=${1:-$(dirname "$0")/../build/rtusim}
scene=${2:-menger}
depth=${3:-6}
width=${4:-160}
height=${5:-90}
preset=${6:-cached}
samples=${7:-4}
kinds=${8:-svo bvh bih kd}
read -r -a extra <<<"${9:-}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "| kind | order | pass | rays | hit rate | cycles/ray | cost/ray | DRAM B/ray | DRAM util | limit |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for kind in $kinds; do
  for order in pixel shuffled; do
    "$rtusim" render --preset "$preset" --core "$kind" --index wide --scene "$scene" \
      --depth "$depth" --width "$width" --height "$height" --order "$order" \
      --passes primary,shadow,ao,diffuse --samples "$samples" --stats "$work/s.json" "${extra[@]}" \
      >"$work/render.txt" 2>&1
    python3 - "$work" "$kind" "$order" <<'PY'
import json, re, sys
work, kind, order = sys.argv[1:4]
report = open(work + "/render.txt").read()
hits = {m[0]: (int(m[1]), int(m[2])) for m in
        re.findall(r"^pass\s+(\w+)\s+(\d+) rays, (\d+) hits", report, re.M)}
primary = re.search(r"^hits\s+(\d+)", report, re.M)
for name, path in [("primary", "s.json"), ("shadow", "s.shadow.json"), ("ao", "s.ao.json"),
                   ("diffuse", "s.diffuse.json"), ("frame", "s.frame.json")]:
    st = json.load(open(f"{work}/{path}"))["statistics"]
    rays = st["rays"]
    if name == "primary":
        rate = f"{int(primary[1]) / rays:.3f}"
    elif name in hits:
        rate = f"{hits[name][1] / hits[name][0]:.3f}"
    else:
        rate = ""
    print(f"| {kind} | {order} | {name} | {rays} | {rate} | {st['cycles_per_ray']:.2f} "
          f"| {st['cost']['mean']:.2f} | {st['memory']['dram']['bytes'] / rays:.1f} "
          f"| {st['utilisation']['dram_bandwidth']:.3f} | {st.get('limit') or 'none'} |")
PY
  done
done
