#include "kinds/bih/projected_triangle.h"

#include <cstdlib>
#include <stdexcept>

#include "kinds/bih/fixed_arith.h"

namespace rtu {
namespace {

using Vector = std::array<int64_t, 3>;

Vector difference(const GridPoint& a, const GridPoint& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

// Exact in 64 bits: grid coordinates below 2^30 give |n_k| < 2^61.
Vector cross(const Vector& a, const Vector& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The smallest index of the largest |n_k| (S4 §2 L200).
uint32_t dominantAxis(const Vector& normal) {
  uint32_t r = 0;
  for (uint32_t k = 1; k < 3; ++k)
    if (std::llabs(normal[k]) > std::llabs(normal[r])) r = k;
  return r;
}

// num / den at scale 2^(m-1), rounded; +1 saturates to the largest code (C2).
int32_t normalCode(int64_t num, int64_t den, const FixedTriangleFormat& f, bool& saturated) {
  const Int128 code = roundHalfEven(Int128(num) * pow2(f.m - 1), den);
  saturated = saturated || code > pow2(f.m - 1) - 1;
  return static_cast<int32_t>(clampTo(code, -pow2(f.m - 1), pow2(f.m - 1) - 1));
}

// num / den at scale 2^(m-1+E), rounded, then clamped into the open (-2^-E, 2^-E).
int32_t edgeCode(int64_t num, int64_t den, const FixedTriangleFormat& f, bool& clamped) {
  const Int128 code = roundHalfEven(Int128(num) * pow2(f.m - 1 + f.E), den);
  const Int128 highest = pow2(f.m - 1) - 1;
  clamped = clamped || code > highest || code < -highest;
  return static_cast<int32_t>(clampTo(code, -highest, highest));
}

}  // namespace

Projection project(const std::array<GridPoint, 3>& x, const FixedTriangleFormat& format,
                   uint32_t source) {
  const Vector e1 = difference(x[1], x[0]), e2 = difference(x[2], x[0]);
  const Vector normal = cross(e1, e2);
  const uint32_t r = dominantAxis(normal), p = (r + 1) % 3, q = (r + 2) % 3;
  const int64_t nr = normal[r];
  Projection out;
  if (nr == 0) return out;
  ProjectedTriangle t;
  t.r = r;
  t.pp = static_cast<uint32_t>(x[0][p]);
  t.pq = static_cast<uint32_t>(x[0][q]);
  t.np = normalCode(normal[p], nr, format, out.saturatedNormal);
  t.nq = normalCode(normal[q], nr, format, out.saturatedNormal);
  const Int128 dot =
      Int128(normal[0]) * x[0][0] + Int128(normal[1]) * x[0][1] + Int128(normal[2]) * x[0][2];
  t.d = static_cast<int64_t>(roundHalfEven(dot, nr));
  t.e1p = edgeCode(e1[p], nr, format, out.clampedEdge);
  t.e1q = edgeCode(e1[q], nr, format, out.clampedEdge);
  t.e2p = edgeCode(e2[p], nr, format, out.clampedEdge);
  t.e2q = edgeCode(e2[q], nr, format, out.clampedEdge);
  t.source = source;
  out.triangle = t;
  return out;
}

ProjectedMesh projectMesh(const TriangleMesh& mesh, const SceneGrid& grid) {
  ProjectedMesh out;
  for (uint32_t i = 0; i < mesh.triangles.size(); ++i) {
    std::array<GridPoint, 3> x;
    for (int k = 0; k < 3; ++k) x[k] = grid.quantise(mesh.vertices[mesh.triangles[i][k]]);
    const Projection projection = project(x, grid.format(), i);
    if (!projection.triangle) {
      ++out.degenerate;
      continue;
    }
    out.triangles.push_back(*projection.triangle);
    out.clampedTriangles += projection.clampedEdge;
    out.saturatedNormals += projection.saturatedNormal;
  }
  return out;
}

namespace {

uint32_t pattern(int32_t code) { return static_cast<uint32_t>(code); }
int32_t code(uint32_t word) { return static_cast<int32_t>(word); }

}  // namespace

std::array<uint32_t, kProjectedTriangleWords> toWords(const ProjectedTriangle& t) {
  const auto d = static_cast<uint64_t>(t.d);
  return {static_cast<uint32_t>(d),
          static_cast<uint32_t>(d >> 32),
          t.r,
          t.pp,
          t.pq,
          pattern(t.np),
          pattern(t.nq),
          pattern(t.e1p),
          pattern(t.e1q),
          pattern(t.e2p),
          pattern(t.e2q),
          t.source};
}

ProjectedTriangle fromWords(const std::array<uint32_t, kProjectedTriangleWords>& w) {
  ProjectedTriangle t;
  t.d = static_cast<int64_t>(uint64_t(w[0]) | uint64_t(w[1]) << 32);
  t.r = w[2];
  t.pp = w[3];
  t.pq = w[4];
  t.np = code(w[5]);
  t.nq = code(w[6]);
  t.e1p = code(w[7]);
  t.e1q = code(w[8]);
  t.e2p = code(w[9]);
  t.e2q = code(w[10]);
  t.source = w[11];
  return t;
}

std::array<uint8_t, 36> toC99Accels(const ProjectedTriangle& t, const FixedTriangleFormat& format) {
  if (format.n > 29)
    throw std::invalid_argument("the C99 accels_t holds n <= 29 (pp has 29 bits, d 32)");
  const uint32_t words[9] = {static_cast<uint32_t>(static_cast<int32_t>(t.d)),
                             t.r | t.pp << 2,
                             t.pq,
                             pattern(t.np),
                             pattern(t.nq),
                             pattern(t.e1q),
                             pattern(t.e2q),
                             pattern(t.e1p),
                             pattern(t.e2p)};
  std::array<uint8_t, 36> bytes;
  for (int i = 0; i < 36; ++i) bytes[i] = static_cast<uint8_t>(words[i / 4] >> (8 * (i % 4)));
  return bytes;
}

}  // namespace rtu
