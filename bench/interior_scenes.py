#!/usr/bin/env python3
"""Stand-ins for seed 003's interior and technical scenes (its Table 6 "BVH cost": Sponza 136.74 and
Graphics Card 225.17 against Armadillo 48.56, i.e. 2.8 and 4.6 times a closed scanned mesh), which
Debian does not ship: deterministic procedural meshes written as OBJ.
  atrium   Sponza-like: a court with two storeys of arcades (n-gon columns, tessellated arches),
           floor, walls, galleries and a roof around an opening, the flat parts as fans of long
           slivers from a corner, as CAD exports triangulate them (what makes such scenes costly).
  board    Graphics-Card-like: a thin board with hundreds of small chips, a heatsink's thin fins
           and long slivers (traces).
Usage: bench/interior_scenes.py OUTDIR   (writes OUTDIR/atrium.obj and OUTDIR/board.obj)
Measured with `rtusim build --accel bvh --builder langr --mesh F --stats F.json` (docs/performance.md).
"""
import math
import os
import random
import sys


class Mesh:
    def __init__(self):
        self.vertices, self.faces = [], []

    def quad(self, a, b, c, d):
        base = len(self.vertices) + 1
        self.vertices += [a, b, c, d]
        self.faces += [(base, base + 1, base + 2), (base, base + 2, base + 3)]

    def grid(self, origin, du, dv, nu, nv):
        """A flat rectangle origin + s du + t dv (s, t in [0, 1]) as nu x nv quads."""
        def at(i, j):
            return tuple(origin[k] + du[k] * i / nu + dv[k] * j / nv for k in range(3))
        for i in range(nu):
            for j in range(nv):
                self.quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1))

    def fan(self, origin, du, dv, n):
        """The rectangle origin + s du + t dv as a fan of 2n slivers from its corner `origin` to
        n points along each far edge, as CAD exports triangulate walls and floors."""
        def at(s, t):
            return tuple(origin[k] + du[k] * s + dv[k] * t for k in range(3))
        rim = [at(1, i / n) for i in range(n + 1)] + [at(1 - i / n, 1) for i in range(1, n + 1)]
        base = len(self.vertices) + 1
        self.vertices += [at(0, 0)] + rim
        self.faces += [(base, base + i + 1, base + i + 2) for i in range(len(rim) - 1)]

    def box(self, lo, hi):
        x0, y0, z0 = lo
        x1, y1, z1 = hi
        self.quad((x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0))
        self.quad((x0, y0, z1), (x0, y1, z1), (x1, y1, z1), (x1, y0, z1))
        self.quad((x0, y0, z0), (x0, y0, z1), (x1, y0, z1), (x1, y0, z0))
        self.quad((x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1))
        self.quad((x0, y0, z0), (x0, y1, z0), (x0, y1, z1), (x0, y0, z1))
        self.quad((x1, y0, z0), (x1, y0, z1), (x1, y1, z1), (x1, y1, z0))

    def column(self, x, z, y0, y1, radius, sides, rings):
        for r in range(rings):
            ya, yb = y0 + (y1 - y0) * r / rings, y0 + (y1 - y0) * (r + 1) / rings
            for s in range(sides):
                a, b = 2 * math.pi * s / sides, 2 * math.pi * (s + 1) / sides
                pa = (x + radius * math.cos(a), z + radius * math.sin(a))
                pb = (x + radius * math.cos(b), z + radius * math.sin(b))
                self.quad((pa[0], ya, pa[1]), (pb[0], ya, pb[1]), (pb[0], yb, pb[1]),
                          (pa[0], yb, pa[1]))

    def arch(self, x0, x1, z, y, depth, thickness, segments, along_x=True):
        """A half-annulus between two columns: its underside, its front and back faces."""
        centre, r = (x0 + x1) / 2, (x1 - x0) / 2

        def point(angle, radius, offset):
            u = centre + radius * math.cos(angle)
            v = y + radius * math.sin(angle)
            return (u, v, z + offset) if along_x else (z + offset, v, u)
        for s in range(segments):
            a, b = math.pi * s / segments, math.pi * (s + 1) / segments
            self.quad(point(a, r, 0), point(b, r, 0), point(b, r, depth), point(a, r, depth))
            for offset in (0, depth):
                self.quad(point(a, r, offset), point(a, r + thickness, offset),
                          point(b, r + thickness, offset), point(b, r, offset))

    def write(self, path):
        with open(path, "w") as f:
            f.write("# rtusim bench/interior_scenes.py\n")
            for v in self.vertices:
                f.write("v %.6f %.6f %.6f\n" % v)
            for t in self.faces:
                f.write("f %d %d %d\n" % t)


def atrium():
    m = Mesh()
    w, d, h = 40.0, 20.0, 16.0  # the court, x by z, two storeys of 8
    m.fan((0, 0, 0), (w, 0, 0), (0, 0, d), 16)  # floor
    for (o, du) in (((0, 0, 0), (w, 0, 0)), ((0, 0, d), (w, 0, 0))):
        m.fan(o, du, (0, h, 0), 16)  # long walls
    for o in ((0, 0, 0), (w, 0, 0)):
        m.fan(o, (0, 0, d), (0, h, 0), 16)  # end walls
    # The roof: a frame of 4 m around an opening over the court's middle.
    m.fan((0, h, 0), (w, 0, 0), (0, 0, 4), 16)
    m.fan((0, h, d - 4), (w, 0, 0), (0, 0, 4), 16)
    m.fan((0, h, 4), (4, 0, 0), (0, 0, d - 8), 16)
    m.fan((w - 4, h, 4), (4, 0, 0), (0, 0, d - 8), 16)
    # Two storeys of arcades along the long walls, 3 m in front of them: 16 bays each.
    for storey in range(2):
        y0 = 8.0 * storey
        for z in (3.0, d - 3.0):
            for i in range(17):
                m.column(2.0 + 2.25 * i, z, y0, y0 + 5.5, 0.3, 16, 4)
            for i in range(16):
                m.arch(2.3 + 2.25 * i, 4.0 + 2.25 * i, z - 0.3, y0 + 5.5, 0.6, 0.5, 16)
        m.fan((1.5, y0 + 7.5, 0), (37, 0, 0), (0, 0, 3.3), 16)  # the galleries' floors
        m.fan((1.5, y0 + 7.5, d - 3.3), (37, 0, 0), (0, 0, 3.3), 16)
    return m


def board():
    m = Mesh()
    rng = random.Random(3)
    m.box((0, 0, 0), (26.0, 0.16, 11.0))  # the board, 260 x 110 mm in cm
    for _ in range(2200):  # small chips and passives
        x, z = rng.uniform(0.2, 25.5), rng.uniform(0.2, 10.5)
        sx, sz = rng.uniform(0.1, 0.6), rng.uniform(0.1, 0.6)
        m.box((x, 0.16, z), (x + sx, 0.16 + rng.uniform(0.05, 0.25), z + sz))
    for i in range(240):  # the heatsink: thin fins over the middle
        x = 6.0 + 0.05 * i
        m.box((x, 0.5, 2.0), (x + 0.02, 3.5, 9.0))
    for _ in range(1600):  # traces: long slivers on the board
        if rng.random() < 0.5:
            x, z = rng.uniform(0, 20), rng.uniform(0, 11)
            m.box((x, 0.16, z), (x + rng.uniform(2, 6), 0.161, z + 0.01))
        else:
            x, z = rng.uniform(0, 26), rng.uniform(0, 8)
            m.box((x, 0.16, z), (x + 0.01, 0.161, z + rng.uniform(1, 3)))
    return m


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    for name, make in (("atrium", atrium), ("board", board)):
        mesh = make()
        path = os.path.join(out, name + ".obj")
        mesh.write(path)
        print("%s: %d triangles" % (path, len(mesh.faces)))


if __name__ == "__main__":
    main()
