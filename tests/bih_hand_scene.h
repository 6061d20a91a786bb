#pragma once
// The BIH hand scene of tests/test_bih_*.cpp on the 4-bit grid of kFourBitC99: four triangles in
// planes z = const with integer vertices, their box [0, 15] x [0, 7] x [0, 3], so the grid's scale
// is 1 and every vertex is its own grid point. Each is a right triangle (x0, y0), (x0 + a, y0),
// (x0, y0 + a) with legs a along x and y:
//   T0  z = 0, (0, 0), a = 6   box x [0, 6],   y [0, 6]   centre sums x 6,  y 6
//   T1  z = 2, (2, 0), a = 7   box x [2, 9],   y [0, 7]   centre sums x 11, y 7
//   T2  z = 1, (11, 0), a = 4  box x [11, 15], y [0, 4]   centre sums x 26, y 4
//   T3  z = 3, (12, 3), a = 3  box x [12, 15], y [3, 6]   centre sums x 27, y 9

#include "bih_formats.h"
#include "geometry/triangle_mesh.h"

namespace rtu {

inline TriangleMesh bihHandMesh() {
  TriangleMesh mesh;
  const auto add = [&mesh](double x0, double y0, double z, double a) {
    const auto first = static_cast<uint32_t>(mesh.vertices.size());
    mesh.vertices.push_back({x0, y0, z});
    mesh.vertices.push_back({x0 + a, y0, z});
    mesh.vertices.push_back({x0, y0 + a, z});
    mesh.triangles.push_back({first, first + 1, first + 2});
  };
  add(0, 0, 0, 6);
  add(2, 0, 2, 7);
  add(11, 0, 1, 4);
  add(12, 3, 3, 3);
  return mesh;
}

}  // namespace rtu
