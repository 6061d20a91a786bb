#pragma once
// The precision study of the triangle formats (issue 27 §4, docs/precision.md, "Triangle
// formats"): each triangle test in its number format against the float64 watertight oracle
// (geometry/triangle_oracle.h) on the mesh's own vertices and the world rays, ray by ray.
//   fixed          seed 004's format (n, m, E, T, C; either listing): the mesh quantised on its
//                  n-bit grid, the BIH built there and traced by the golden traversal with the
//                  listing's kernel (C is the traversal's, so the structure is part of the format)
//   unit-triangle  seed 001's binary32 test (kd_units.h INT) on the stored float24 matrices, in
//                  hardware space, with IEEE or the truncating divider; the list unit's rule (the
//                  later of equal t)
//   float32 Moller-Trumbore and watertight (geometry/triangle_tests.h), the BVH core's tests
// The float tests loop over every triangle (the structure's boxes are outward-rounded, so only
// the test decides), keeping the nearest (the first of equal t).
//
// Per view or random ray: a false hit (the format hits, float64 misses), a missed hit (the
// reverse), a hit on another triangle (of them, how many share no vertex with the oracle's: not a
// tie at an edge), and over the rays where both hit the same triangle the relative t error
// |t - t64| / t64. Holes: of the rays aimed at a vertex or an edge midpoint that two or more
// triangles share, that cross the surface there (every such triangle faces the ray the same way:
// not a silhouette, which a ray only grazes) and whose oracle hit is one of those triangles (the
// edge rays), the ones where the format hits none of them: the ray passed through the mesh at the
// feature. Aimed rays count only there: aimed at a silhouette they graze it, and either answer
// is right.
// Self-intersection (fixed formats, S4 §2.1.5): from every hit, the hit point h = O + t ω with
// one more fractional bit rounded to the grid, a secondary ray in a random direction from
// h ± 2 grid units per axis (`O[k] = h[k] + ((dt > 0) ^ (n[k] < 0) ? 2 : -2)`, dt = n . ω, n the
// grid triangle's normal) and from h itself; a self-hit is a nearest hit on the same triangle.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/ray.h"
#include "geometry/ray_sets.h"
#include "geometry/triangle_mesh.h"
#include "geometry/triangle_oracle.h"
#include "kinds/bih/fixed_format.h"
#include "kinds/kd/binary32.h"

namespace rtu {

enum class TriangleArithmetic { Fixed, UnitTriangle, MollerTrumbore32, Watertight32 };

// One row's triangle test and number format.
struct TriangleFormatSpec {
  TriangleArithmetic arithmetic = TriangleArithmetic::Fixed;
  FixedTriangleFormat fixed = kC99Format;  // Fixed
  Division division = Division::Ieee;      // UnitTriangle: the divider
  std::string swept;                       // the parameter the row varies (n, m, E, T, C) or ""

  // "c99 n=29 m=32 E=10 T=0 C=16", "vhdl n=30 ...", "binary32 unit-triangle (ieee division)",
  // "float32 moller-trumbore", "float32 watertight".
  std::string name() const;
  // "bih" for the fixed formats, "all triangles" for the others.
  std::string structure() const;
};

struct TriangleRayCounts {
  uint64_t rays = 0, referenceHits = 0, hits = 0;
  uint64_t falseHits = 0, missedHits = 0, otherTriangle = 0, otherNotAdjacent = 0;
  uint64_t sameTriangle = 0;            // both hit the same triangle: the t error's rays
  double tErrorMax = 0, tErrorSum = 0;  // relative, |t - t64| / t64
  uint64_t edgeRays = 0, holes = 0;     // rays aimed at shared vertices and edges (not in rays)

  double tErrorMean() const { return sameTriangle ? tErrorSum / double(sameTriangle) : 0; }
};

struct SelfIntersection {
  uint64_t secondaryRays = 0;  // one per hit
  uint64_t selfHitsOffset = 0, selfHitsNoOffset = 0;
};

struct TriangleFormatPrecision {
  TriangleFormatSpec spec;
  TriangleRayCounts counts;
  // Fixed only: triangles degenerate on the grid (dropped), with clamped edges, and the study of
  // secondary rays from the hits.
  uint32_t degenerate = 0, clamped = 0;
  std::optional<SelfIntersection> self;
};

// What a format found for one ray: t along the world ray's direction and the mesh's triangle.
struct FormatHit {
  double t = 0;
  uint32_t triangle = 0;
};

// The rays of a study: views and random rays, then rays aimed at vertices and edge midpoints.
struct TriangleRaySettings {
  int views = 4, viewSize = 64;  // views of viewSize x viewSize rays around the mesh's box
  size_t randomRays = 4096, aimedRays = 4096;
  uint64_t seed = 1;
};

class TrianglePrecisionStudy {
 public:
  // The oracle's answer to every ray, computed here once.
  TrianglePrecisionStudy(const TriangleMesh& mesh, std::vector<Ray> rays,
                         std::vector<AimedRay> aimed);
  TrianglePrecisionStudy(const TriangleMesh& mesh, const TriangleRaySettings& settings);

  size_t rays() const { return rays_.size() + aimed_.size(); }
  size_t aimedRays() const { return aimed_.size(); }
  // Throws what SceneGrid and validateFixedTriangleFormat throw for a fixed format.
  TriangleFormatPrecision measure(const TriangleFormatSpec& spec) const;

  // The counts of any closest-hit search `closest` (a Ray to an optional<FormatHit>).
  template <class Closest>
  TriangleRayCounts count(Closest&& closest) const {
    TriangleRayCounts counts;
    for (size_t i = 0; i < rays(); ++i) countRay(i, closest(ray(i)), counts);
    return counts;
  }

 private:
  const Ray& ray(size_t i) const {
    return i < rays_.size() ? rays_[i] : aimed_[i - rays_.size()].ray;
  }
  void countRay(size_t i, const std::optional<FormatHit>& got, TriangleRayCounts& counts) const;
  void countAimed(size_t i, const std::optional<OracleHit>& ref,
                  const std::optional<FormatHit>& got, TriangleRayCounts& counts) const;
  bool adjacent(uint32_t a, uint32_t b) const;
  TriangleFormatPrecision measureFixed(const TriangleFormatSpec& spec) const;

  const TriangleMesh& mesh_;
  std::vector<Ray> rays_;
  std::vector<AimedRay> aimed_;
  std::vector<std::optional<OracleHit>> oracle_;  // rays_ then aimed_
  std::vector<std::array<uint32_t, 3>> corners_;  // each triangle's corners, welded by position
  std::vector<std::vector<uint32_t>> incident_;   // per aimed ray: triangles at its feature
  uint64_t seed_ = 1;
};

// The rows a sweep measures: the c99 prototype's format, then each value of each list varied
// alone from it (skipping the prototype again), the VHDL listing's format, the unit-triangle
// test with either divider, and the float32 tests.
struct TriangleSweep {
  std::vector<int> n, m, E, T, C;
};
std::vector<TriangleFormatSpec> sweepRows(const TriangleSweep& sweep);

// Seed 004's stress test (S4 §2.5.1): a triangle through the box's diagonal from (0, 0, 0) to
// (1, 1, 1) with its third vertex at the centre moved sideways by `width` along (1, -1, 0)/sqrt 2,
// long and thin (the seed widened its near-degenerate triangle "until it formed a thin line at an
// image resolution of 640x480").
TriangleMesh stressTriangle(double width);

}  // namespace rtu
