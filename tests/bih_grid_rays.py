#!/usr/bin/env python3
"""Ray records moved onto a BIH's grid, for the CLI tests of BIH images (whose records are grid
coordinates: docs/triangles.md). Usage: bih_grid_rays.py S.BVH S.BIH RAYS OUT [SCALE_OUT]

The mesh's float32 box is the BVH's triangle records' (the same mesh built as both), the grid's
scale (2^n - 1) over its longest side, n from the BIH header's format word. Writes OUT with each
record's origin on the grid and model address 0, and SCALE_OUT with "scale n"."""
import struct
import sys


def words(path):
    raw = open(path, "rb").read()
    return struct.unpack("<%dI" % (len(raw) // 4), raw), struct.unpack("<%df" % (len(raw) // 4), raw)


bvh, bvhf = words(sys.argv[1])
bih, _ = words(sys.argv[2])
base, count = bvh[8], bvh[9]
points = [bvhf[base + 12 * t + k: base + 12 * t + k + 3] for t in range(count) for k in (0, 3, 6)]
lower = [min(p[a] for p in points) for a in range(3)]
upper = [max(p[a] for p in points) for a in range(3)]
n = bih[14] & 63  # header word 14: the format, n in bits 5:0
scale = (2 ** n - 1) / max(u - l for u, l in zip(upper, lower))
raw = open(sys.argv[3], "rb").read()
out = b""
for i in range(len(raw) // 32):
    r = struct.unpack("<I6fI", raw[32 * i:32 * i + 32])
    origin = [(r[1 + a] - lower[a]) * scale for a in range(3)]
    out += struct.pack("<I6fI", r[0], *origin, *r[4:7], 0)
open(sys.argv[4], "wb").write(out)
if len(sys.argv) > 5:
    open(sys.argv[5], "w").write("%r %d" % (scale, n))
