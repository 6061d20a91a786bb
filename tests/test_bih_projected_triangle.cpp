// Seed 004's triangle precompute (kinds/bih/projected_triangle.h) against exact rationals worked
// out by hand: each field is the exact quotient rounded once, half to even.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "bih_formats.h"
#include "geometry/ray_sets.h"
#include "kinds/bih/projected_triangle.h"

namespace rtu {
namespace {

// x0 + 4096 (3, 4, 2) and x0 + 4096 (1, 5, 8): n = 4096^2 ((3,4,2) x (1,5,8)) =
// 2^24 (4*8 - 2*5, 2*1 - 3*8, 3*5 - 4*1) = 2^24 (22, -22, 11).
std::array<GridPoint, 3> spotTriangle(const GridPoint& x0) {
  return {x0, GridPoint{x0[0] + 3 * 4096, x0[1] + 4 * 4096, x0[2] + 2 * 4096},
          GridPoint{x0[0] + 4096, x0[1] + 5 * 4096, x0[2] + 8 * 4096}};
}

}  // namespace

TEST_CASE("BIH projected triangle: exact rationals rounded once (n = 29, m = 32, E = 10)",
          "[bih]") {
  const Projection projection = project(spotTriangle({1000, 2000, 3000}), kC99Format, 7);
  REQUIRE(projection.triangle);
  const ProjectedTriangle& t = *projection.triangle;
  // |n_0| = |n_1| = 22 2^24: the smallest index wins, r = 0, p = 1, q = 2.
  CHECK(t.r == 0);
  CHECK(t.pp == 2000);
  CHECK(t.pq == 3000);
  CHECK(t.np == -2147483648);  // -22/22 = -1 = -2^31, representable
  CHECK(t.nq == 1073741824);   // 11/22 = 1/2 = 2^30
  // d = x0_r + pp np + pq nq = 1000 - 2000 + 1500.
  CHECK(t.d == 500);
  // e_ik = (x_i,k - x0_k) / n_r at scale 2^41, with x_i,k - x0_k = 4096 c and n_r = 22 2^24:
  // c 2^12 2^41 / (22 2^24) = c 2^28 / 11.
  CHECK(t.e1p == 97612893);   // c = 4: 2^30 / 11 = 97612893.09
  CHECK(t.e1q == 48806447);   // c = 2: 2^29 / 11 = 48806446.55
  CHECK(t.e2p == 122016116);  // c = 5: 5 2^28 / 11 = 122016116.36
  CHECK(t.e2q == 195225786);  // c = 8: 2^31 / 11 = 195225786.18
  CHECK(t.source == 7);
  CHECK_FALSE(projection.clampedEdge);
  CHECK_FALSE(projection.saturatedNormal);
}

TEST_CASE("BIH projected triangle: d rounds half to even", "[bih]") {
  // The same normal from x0 = (1, 2, 3): d = 1 - 2 + 3/2 = 0.5 -> 0; from (2, 2, 3): 1.5 -> 2.
  CHECK(project(spotTriangle({1, 2, 3}), kC99Format, 0).triangle->d == 0);
  CHECK(project(spotTriangle({2, 2, 3}), kC99Format, 0).triangle->d == 2);
}

TEST_CASE("BIH projected triangle: np = +1 saturates, a zero edge component stays 0", "[bih]") {
  // e1 = (8, -8, 0), e2 = (0, 0, 8): n = (-8*8 - 0, 0 - 8*8, 0) = (-64, -64, 0); r = 0, p = 1,
  // q = 2; np = -64/-64 = +1 -> 2^5 - 1 = 31 (C2), nq = 0.
  const Projection projection = project({GridPoint{0, 8, 0}, {8, 0, 0}, {0, 8, 8}}, kFourBit, 0);
  REQUIRE(projection.triangle);
  const ProjectedTriangle& t = *projection.triangle;
  CHECK(projection.saturatedNormal);
  CHECK_FALSE(projection.clampedEdge);
  CHECK(t.r == 0);
  CHECK(t.np == 31);
  CHECK(t.nq == 0);
  CHECK(t.pp == 8);
  CHECK(t.pq == 0);
  CHECK(t.d == 8);  // <n, x0> / n_r = (-64 * 8) / -64
  // e1p = (0 - 8) / -64 = 1/8 -> 16; e1q = (0 - 0) / -64 = 0; e2p = 0; e2q = 8 / -64 -> -16.
  CHECK(t.e1p == 16);
  CHECK(t.e1q == 0);
  CHECK(t.e2p == 0);
  CHECK(t.e2q == -16);
}

TEST_CASE("BIH projected triangle: edges at or beyond 2^-E are clamped, counted", "[bih]") {
  // Legs of 4: n = (0, 0, 16), e1p = e2q = 4/16 = 2^-2 = 2^-E: 32 codes, outside the open
  // interval, clamped to 31.
  const Projection four = project({GridPoint{0, 0, 0}, {4, 0, 0}, {0, 4, 0}}, kFourBit, 0);
  CHECK(four.clampedEdge);
  CHECK(four.triangle->e1p == 31);
  CHECK(four.triangle->e2q == 31);
  // Mirrored: e1 = (-4, 0, 0), e2 = (0, -4, 0), n = (0, 0, 16): e1p = -1/4 -> -32, which m bits
  // could hold, clamped to -31 all the same: the interval is open.
  const Projection mirrored = project({GridPoint{4, 4, 0}, {0, 4, 0}, {4, 0, 0}}, kFourBit, 0);
  CHECK(mirrored.clampedEdge);
  CHECK(mirrored.triangle->e1p == -31);
  // Legs of 5: 5/25 = 0.2 -> 25.6 -> 26 codes, inside.
  const Projection five = project({GridPoint{0, 0, 0}, {5, 0, 0}, {0, 5, 0}}, kFourBit, 0);
  CHECK_FALSE(five.clampedEdge);
  CHECK(five.triangle->e1p == 26);
}

TEST_CASE("BIH projected triangle: a mesh's degenerate, clamped and saturated triangles", "[bih]") {
  TriangleMesh mesh;
  // The box [0, 15]^3 on 4 bits: scale 1, vertices keep their coordinates.
  mesh.vertices = {{0, 0, 0}, {15, 15, 15}, {0, 8, 0}, {8, 0, 0}, {0, 8, 8},
                   {4, 0, 0}, {0, 4, 0},    {1, 1, 1}, {2, 2, 2}, {15, 0, 0}};
  mesh.triangles = {{2, 3, 4},   // np = +1: saturated
                    {0, 5, 6},   // legs of 4: clamped
                    {0, 7, 8},   // collinear: omitted
                    {0, 9, 1}};  // n = (0, -225, 225): |e| = 15/225 = 1/15 < 1/4
  const ProjectedMesh projected = projectMesh(mesh, SceneGrid(meshBounds(mesh), kFourBit));
  CHECK(projected.degenerate == 1);
  CHECK(projected.clampedTriangles == 1);
  CHECK(projected.saturatedNormals == 1);
  REQUIRE(projected.triangles.size() == 3);
  CHECK(projected.triangles[2].source == 3);
}

TEST_CASE("BIH projected triangle: the 12-word record and the seed's 36-byte accels_t", "[bih]") {
  const ProjectedTriangle t = *project(spotTriangle({1000, 2000, 3000}), kC99Format, 7).triangle;
  const auto words = toWords(t);
  const std::array<uint32_t, 12> expected = {
      500, 0, 0, 2000, 3000, 0x80000000, 0x40000000, 97612893, 48806447, 122016116, 195225786, 7};
  CHECK(words == expected);
  CHECK(toWords(fromWords(words)) == words);
  ProjectedTriangle negative;
  negative.d = -5;  // two's complement over both words
  CHECK(toWords(negative)[0] == 0xFFFFFFFB);
  CHECK(toWords(negative)[1] == 0xFFFFFFFF);
  CHECK(fromWords(toWords(negative)).d == -5);

  // accels_t: d, r | pp << 2 (2000 << 2 = 8000), pq, np, nq, e1q, e2q, e1p, e2p, little endian.
  const auto bytes = toC99Accels(t, kC99Format);
  std::array<uint32_t, 9> read{};
  for (int i = 0; i < 36; ++i) read[i / 4] |= uint32_t(bytes[i]) << (8 * (i % 4));
  const std::array<uint32_t, 9> accels = {500,      8000,      3000,     0x80000000, 0x40000000,
                                          48806447, 195225786, 97612893, 122016116};
  CHECK(read == accels);
  CHECK(bytes[4] == 0x40);  // 8000 = 0x1F40, low byte first
  CHECK(bytes[5] == 0x1F);
  CHECK_THROWS_AS(toC99Accels(t, kVhdlFormat), std::invalid_argument);  // n = 30: pp is 29 bits
}

}  // namespace rtu
