#pragma once
// The arithmetic of seed 001's ray pipe, one function per unit, in binary32 as binary32.h computes
// it (flush-to-zero, RNE, the divider chosen by Division), each operation in the RTL's order. The
// traversal's control (which child, the short stack, the list unit) is kd_traversal.h's; these
// only compute. Everything is in hardware space (x and y swapped from world, reading K4).
//
// SINT (R1 RAYTRACER/scene_int/scene_int_pl.sv; specs/001 §2.2 "Scene intersection unit"): per
//   axis t1 = (min + -o) / d and t2 = (max + -o) / d, swapped when d's sign bit is set (so -0
//   counts as negative); the x interval, then y and z each: a miss if the interval's entry is
//   beyond the axis' exit or the axis' entry beyond the interval's exit, the entry the greater
//   and the exit the lesser (by altfp_compare's agb, so a NaN takes the axis' value); a miss if
//   EPSILON > exit; t_min = entry > EPSILON ? entry : EPSILON; t_max as KdTMaxClamp says.
// TRAV (R1 RAYTRACER/trav/trav_math.sv): diff = split + -o, t_mid = diff / d; the origin is above
//   the split when diff's sign bit is set (equality is the low side), the direction positive when
//   d's sign bit is clear (-0 is negative), d = 0 is the divider's division-by-zero flag; the four
//   decisions are the RTL's sums of products, which can overlap only when t_mid is NaN.
// INT (R1 RAYTRACER/int/int_math.sv, prime_calc.sv; specs/001 §2.2 "Intersection unit"): per row
//   r, o'_r = (m_r1 ox + m_r2 oy) + (m_r3 oz + t_r) and d'_r = (m_r1 dx + m_r2 dy) + m_r3 dz;
//   t = o'_z / -d'_z, u = o'_x + d'_x t, v = o'_y + d'_y t; a hit when 1 > u + v, t > EPSILON and
//   neither u's nor v's sign bit is set (-0 misses). u weighs the triangle's A, v its B. There is
//   no t range test: the list unit compares with the leaf's t_max.

#include <array>
#include <cstdint>

#include "kinds/kd/binary32.h"

namespace rtu {

// EPSILON of the RTL (`EPSILON, 0x1E3CE508, about 1e-20): SINT's least t_min, INT's least t.
constexpr uint32_t kTrayRacerEpsilonBits = 0x1E3CE508;

// SINT's t_max. AsBuilt: the RTL's (t_max > 1 and not a shadow ray) ? t_max : 1, which makes every
// primary ray of the demo scenes (directions of length 240 and more) run to t = 1, far beyond the
// box (specs/001 §2.2; experiment A.3). Intended: the box's exit (a shadow ray still ends at 1).
enum class KdTMaxClamp : uint8_t { AsBuilt, Intended };

// A ray as the raystore holds it: origin and direction as binary32 in hardware space.
struct KdRay {
  std::array<float, 3> origin{}, direction{};
  bool shadow = false;
};

struct KdInterval {
  bool miss = false;
  float tMin = 0, tMax = 0;
};

// SINT: the ray against the scene box (hardware x, y, z min then max).
KdInterval sceneIntersection(const KdRay& ray, const std::array<float, 6>& box, KdTMaxClamp clamp,
                             Division division);

// TRAV's plane test at a node splitting `axis` at `split` over the ray's [tMin, tMax].
struct KdPlaneTest {
  bool onlyLow = false, onlyHigh = false, lowThenHigh = false, highThenLow = false;
  float tMid = 0;
};
KdPlaneTest planeTest(const KdRay& ray, uint32_t axis, float split, float tMin, float tMax,
                      Division division);

// INT: the ray against a unit-triangle matrix's 12 entries (uttm.h's order, as the INT unit reads
// them: float24 padded to binary32).
struct KdTriangleHit {
  bool hit = false;
  float t = 0, u = 0, v = 0;
};
KdTriangleHit intersectUnitTriangle(const KdRay& ray, const std::array<float, 12>& matrix,
                                    Division division);

}  // namespace rtu
