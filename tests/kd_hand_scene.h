#pragma once
// A k-d scene small enough to follow by hand (hardware space; box [0, 8] x [0, 2] x [0, 2]):
// triangles in planes x = c facing -x, each with C = (c, 0, 0), A = C + s (0, 1, 0) and
// B = C + s (0, 0, 1), so that a ray along +x from (0, y, z) crosses it at t = c - ox with
// u = y / s, v = z / s, a hit when y + z < s. N = (-1, 0, 0), so N - C = (-1 - c, 0, 0) and the
// matrix's rows are (0, 1 / s, 0 | 0), (0, 0, 1 / s | 0), (-1 / (1 + c), 0, 0 | c / (1 + c)): with
// c of 1, 3 or 7 and s of 1 or 2 every entry is exact in float24.
//   T0: c = 1, s = 1     T1: c = 3, s = 1     T2: c = 7, s = 2     T3: T1 again
// Nodes (axis x throughout):
//   0: split 4, low 1, high 4
//   1: split 2, low 2, high 3
//   2: leaf, list [T0]            x in [0, 2]
//   3: leaf, list [T1, T3]        x in [2, 4]
//   4: leaf, list [T2]            x in [4, 8]

#include "base/float_bits.h"
#include "kinds/kd/kd_image.h"

namespace rtu {

inline UttmWords handUttm(double c, double s) {
  return packUttm(unitTriangleMatrix({c, s, 0}, {c, 0, s}, {c, 0, 0}));
}

inline TrayRacerNode handInterior(float split, uint32_t high) {
  TrayRacerNode node;
  node.axis = 0;
  node.splitBits = floatBits(split);
  node.high = high;
  return node;
}

inline TrayRacerNode handLeaf(uint32_t listIndex, uint32_t count) {
  TrayRacerNode node;
  node.leaf = true;
  node.listIndex = listIndex;
  node.count = count;
  return node;
}

inline TrayRacerScene handKdScene() {
  TrayRacerScene scene;
  scene.nodes = {handInterior(4, 4), handInterior(2, 3), handLeaf(0, 1), handLeaf(1, 2),
                 handLeaf(3, 1)};
  scene.lists = {0, 1, 3, 2};
  scene.uttms = {handUttm(1, 1), handUttm(3, 1), handUttm(7, 2), handUttm(3, 1)};
  scene.box = {0, 0, 0, 8, 2, 2};
  return scene;
}

}  // namespace rtu
