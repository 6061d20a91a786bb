#pragma once
// Seed 004's triangle record: Badouel's test in Wald's projected form, precomputed from the
// triangle's grid vertices (S4 §2 p.23 L196-214). n = (x1 - x0) x (x2 - x0); r = the smallest
// index of the largest |n_k| (a triangle with n_r = 0 is omitted); p = (r + 1) mod 3,
// q = (r + 2) mod 3; pp = x0_p, pq = x0_q; np = n_p / n_r, nq = n_q / n_r;
// d = <n, x0> / n_r; e_ik = (x_i,k - x0_k) / n_r for i in {1, 2}, k in {p, q}.
//
// Every field is computed exactly from the integers (n in 64 bits, the quotients in 128) and
// rounded once to its format (fixed_format.h), half to even (plan reading C4; the seed leaves the
// rounding open, "careful rounding" for d, L299-305). Edges are clamped to the open (-2^-E, 2^-E),
// i.e. to ±(2^(m-1) - 1) codes (§2.1.3 L289-295); np, nq = +1, not representable at scale
// 2^(m-1), saturate to 2^(m-1) - 1 (C2). Both are reported so a mesh's clamped triangles and
// saturated normals can be counted.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/triangle_mesh.h"
#include "kinds/bih/fixed_format.h"
#include "kinds/bih/grid.h"

namespace rtu {

struct ProjectedTriangle {
  int64_t d = 0;    // (n+3)-bit signed grid integer
  uint32_t r = 0;   // 0, 1, 2: the axis the triangle is projected along
  uint32_t pp = 0;  // x0_p, n bits
  uint32_t pq = 0;  // x0_q, n bits
  int32_t np = 0;   // scale 2^(m-1)
  int32_t nq = 0;   // scale 2^(m-1)
  int32_t e1p = 0;  // scale 2^(m-1+E)
  int32_t e1q = 0;
  int32_t e2p = 0;
  int32_t e2q = 0;
  uint32_t source = 0;  // the mesh's triangle index
};

struct Projection {
  std::optional<ProjectedTriangle> triangle;  // none: degenerate on the grid (n_r = 0)
  bool clampedEdge = false;      // an edge code fell outside the open interval and was clamped
  bool saturatedNormal = false;  // np or nq was +1 and saturated
};

Projection project(const std::array<GridPoint, 3>& vertices, const FixedTriangleFormat& format,
                   uint32_t source);

struct ProjectedMesh {
  std::vector<ProjectedTriangle> triangles;  // in the mesh's order, degenerate ones left out
  uint32_t degenerate = 0;                   // omitted: zero area once on the grid
  uint32_t clampedTriangles = 0;             // triangles with at least one clamped edge
  uint32_t saturatedNormals = 0;             // triangles with np or nq saturated
};

// Every triangle of `mesh`, its vertices quantised on `grid`.
ProjectedMesh projectMesh(const TriangleMesh& mesh, const SceneGrid& grid);

// rtusim's 12-word record: d low and high (two's complement over 64 bits; n = 30 needs 33),
// r, pp, pq, np, nq, e1p, e1q, e2p, e2q, source. Codes are stored as their 32-bit patterns.
inline constexpr uint32_t kProjectedTriangleWords = 12;
std::array<uint32_t, kProjectedTriangleWords> toWords(const ProjectedTriangle& triangle);
ProjectedTriangle fromWords(const std::array<uint32_t, kProjectedTriangleWords>& words);

// The seed's 36-byte C99 `accels_t` (S4 §2.1.4 p.27 L305-330), little endian as on x86 with GCC's
// bit fields LSB first: d (int32); r in bits 1:0 and pp in bits 30:2 of one word; pq; np; nq;
// e1q; e2q; e1p; e2p. Throws std::invalid_argument unless format.n <= 29 (pp has 29 bits, d 32).
std::array<uint8_t, 36> toC99Accels(const ProjectedTriangle& triangle,
                                    const FixedTriangleFormat& format);

}  // namespace rtu
