#!/usr/bin/env bash
# Secondary rays on every kind (issue 32, docs/workloads.md "The triangle kinds on the same
# passes"): a camera frame's primary rays and the shadow, AO (4 samples) and reflected rays spawned
# from the octree's golden hits, replayed on the SVO core and on the BVH, BIH and k-d cores built
# over the same scene's voxel faces (the same surfaces; the rays start 2^-12 off them), each
# alone on the cycle-accurate model with the preset's memory; and the shadow and AO rays again as
# rays taking the nearest hit ahead (span bits 01 for 10: what any-hit saves, though the nearest
# hit may lie beyond the segment). Prints one markdown row per kind and workload: rays, hit rate,
# cycles per ray, cost per ray, triangle tests per ray, DRAM bytes per ray and utilisation.
# Usage: bench/secondary_rays_triangles.sh [rtusim] [scene] [depth] [width] [height] [preset]
set -euo pipefail

rtusim=${1:-$(dirname "$0")/../build/rtusim}
scene=${2:-menger}
depth=${3:-6}
width=${4:-160}
height=${5:-90}
preset=${6:-cached}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

header=$("$rtusim" build --scene "$scene" --depth "$depth" --out "$work/m.svo" --model-header |
  sed -n 's/.*model header at word \([0-9]*\).*/\1/p')
"$rtusim" build --accel bvh --scene "$scene" --depth "$depth" --out "$work/m.bvh" >/dev/null
"$rtusim" build --accel bih --index wide --scene "$scene" --depth "$depth" --out "$work/m.bih" \
  >/dev/null 2>&1
"$rtusim" build --accel kdtree --index wide --scene "$scene" --depth "$depth" \
  --out "$work/m.kd" >/dev/null 2>&1

# The records against an image without a model header (model address 0); for the BIH on its grid:
# the origin moved and scaled, the direction scaled alike, so t keeps its units (a span's t = 1).
to_image() {  # to_image rays.bin out.bin [bih]
  python3 - "$work/m.bvh" "$work/m.bih" "$@" <<'PY'
import struct, sys
def words(path):
    raw = open(path, "rb").read()
    return struct.unpack("<%dI" % (len(raw) // 4), raw), struct.unpack("<%df" % (len(raw) // 4), raw)
bvh, bvhf = words(sys.argv[1])
bih, _ = words(sys.argv[2])
grid = len(sys.argv) > 5
lower, scale = [0.0] * 3, 1.0
if grid:
    base, count = bvh[8], bvh[9]
    points = [bvhf[base + 12 * t + k: base + 12 * t + k + 3] for t in range(count) for k in (0, 3, 6)]
    lower = [min(p[a] for p in points) for a in range(3)]
    upper = [max(p[a] for p in points) for a in range(3)]
    scale = (2 ** (bih[14] & 63) - 1) / max(u - l for u, l in zip(upper, lower))
raw = open(sys.argv[3], "rb").read()
out = bytearray()
for i in range(len(raw) // 32):
    r = struct.unpack("<I6fI", raw[32 * i:32 * i + 32])
    origin = [(r[1 + a] - lower[a]) * scale for a in range(3)]
    direction = [r[4 + a] * scale for a in range(3)]
    out += struct.pack("<I6fI", r[0], *origin, *direction, 0)
open(sys.argv[4], "wb").write(out)
PY
}

echo "| kind | workload | rays | hit rate | cycles/ray | cost/ray | tests/ray | DRAM B/ray | DRAM util |"
echo "|---|---|---|---|---|---|---|---|---|"
# Any-hit records (bit 31 of word 0) as rays taking the nearest hit ahead (bit 30).
as_nearest() {  # as_nearest in.bin out.bin
  python3 - "$@" <<'PY'
import struct, sys
raw = bytearray(open(sys.argv[1], "rb").read())
for i in range(0, len(raw), 32):
    (word,) = struct.unpack_from("<I", raw, i)
    struct.pack_into("<I", raw, i, word & ~(1 << 31) | (1 << 30) if word >> 31 else word)
open(sys.argv[2], "wb").write(raw)
PY
}

frame=(--width "$width" --height "$height")
for type in primary shadow ao reflection shadow-nearest ao-nearest; do
  extra=()
  [[ $type == ao* ]] && extra=(--samples 4)
  if [[ $type == *-nearest ]]; then
    as_nearest "$work/${type%-nearest}.bin" "$work/$type.bin"
  else
    "$rtusim" jobs --svo "$work/m.svo" --model-address "$header" --ray-type "$type" \
      --rays "$work/$type.bin" "${frame[@]}" "${extra[@]}" >/dev/null
  fi
  to_image "$work/$type.bin" "$work/$type.image.bin"
  to_image "$work/$type.bin" "$work/$type.grid.bin" bih
  for kind in svo bvh bih kd; do
    case $kind in
      svo) input=(--svo "$work/m.svo" --rays "$work/$type.bin") ;;
      bih) input=(--core bih --accel-file "$work/m.bih" --rays "$work/$type.grid.bin") ;;
      *) input=(--core "$kind" --accel-file "$work/m.$kind" --rays "$work/$type.image.bin") ;;
    esac
    "$rtusim" replay --preset "$preset" "${input[@]}" --out "$work/out.csv" \
      --stats "$work/s.json" >/dev/null 2>&1
    python3 - "$work/s.json" "$work/out.csv" "$kind" "$type" <<'PY'
import csv, json, sys
st = json.load(open(sys.argv[1]))["statistics"]
kind, rays = sys.argv[3], st["rays"]
if kind == "svo":
    import struct
    data = open(sys.argv[2], "rb").read()
    w = struct.unpack("<%dI" % (len(data) // 4), data)
    hits = sum(w[i + 1] for i in range(0, len(w), 8))
else:
    hits = sum(r["hit"] == "1" for r in csv.DictReader(open(sys.argv[2])))
tests = st.get(kind + "_triangle_tests")
tests = f"{tests / rays:.2f}" if tests is not None else "-"
memory = st["memory"]
print(f"| {kind} | {sys.argv[4]} | {rays} | {hits / rays:.3f} | {st['cycles_per_ray']:.2f} "
      f"| {st['cost']['mean']:.2f} | {tests} | {memory['dram']['bytes'] / rays:.1f} "
      f"| {st['utilisation']['dram_bandwidth']:.3f} |")
PY
  done
done
