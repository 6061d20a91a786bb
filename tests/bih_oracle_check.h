#pragma once
// The check of seed 004's fixed-point hits against the independent oracle
// (geometry/triangle_oracle.h), shared by the kernel's brute-force test (test_bih_oracle.cpp) and
// the BIH traversal's (test_bih_traversal_oracle.cpp). A mesh is quantised to a format's grid;
// the oracle traces the same grid integers in double with the same quantised ray (origin on the
// grid, direction ω / 2^(m-1)), so both measure t in grid units.
//
// Per ray they agree when both miss or both hit the same triangle, or hit two within the t error
// bound below (a shared edge or vertex). Otherwise the disagreement is explained when, for a
// disputed triangle, the exact barycentric margin min(u, v, 1 - u - v) of the ray's crossing with
// its plane is within the kernel's error bound there (docs/triangles.md, "Fixed point"):
//   t:  |dt| <= (dnum + |t| dden) / |den| + 1, with dnum = 1/2 (d rounded) + 1 (the numerator's
//       floor) + (O_p + O_q) 2^-m (np, nq rounded) and dden = 2 2^-(m-1) (two floors) +
//       (|ω_p| + |ω_q|) 2^-m; the final 1 is the truncating division;
//   k:  |dk| <= |dt| max(|ω_p|, |ω_q|) + 1 (the floor of t ω);
//   u:  |du| <= |de1p| |k_q| + |de1q| |k_p| + (|e1p| + |e1q|) |dk|, v likewise, where de is the
//       stored code's distance from the exact edge (half a code, 2^-(m+E), unless clamped);
//   margin bound = |du| + |dv| (1 - u - v errs by both).
// A triangle whose edges were clamped (its de is not small) is counted on its own.

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "geometry/ray_sets.h"
#include "geometry/triangle_oracle.h"
#include "kinds/bih/fixed_kernels.h"

namespace rtu {

struct Agreement {
  int rays = 0, same = 0, ties = 0, explained = 0, clamped = 0, unexplained = 0;
  int falseHits = 0, falseMisses = 0, otherTriangle = 0;
  double largestTError = 0;  // grid units, same triangle hit by both
  int disagreements() const { return explained + clamped + unexplained; }
};

// What a triangle's exact plane says about a ray, and how far the kernel may be from it.
struct ExactCrossing {
  double t = 0, margin = 0;  // margin: min(u, v, 1 - u - v), exact barycentrics
  double tBound = 0, marginBound = 0;
};

// What a fixed-point closest-hit search found: t in grid units and the source triangle.
struct KernelHit {
  int64_t t;
  uint32_t triangle;
};

class FixedOracleCheck {
 public:
  FixedOracleCheck(const TriangleMesh& mesh, const FixedTriangleFormat& format)
      : format_(format), grid_(meshBounds(mesh), format), projected_(projectMesh(mesh, grid_)) {
    held_.triangles = mesh.triangles;
    for (const auto& v : mesh.vertices) {
      const GridPoint g = grid_.quantise(v);
      held_.vertices.push_back({double(g[0]), double(g[1]), double(g[2])});
      gridVertices_.push_back(g);
    }
  }

  const ProjectedMesh& projected() const { return projected_; }

  const SceneGrid& grid() const { return grid_; }

  // Classifies each ray that reaches the box by what `closest` (a GridRay to an
  // optional<KernelHit>) finds against the oracle.
  template <class Closest>
  Agreement compare(const std::vector<Ray>& rays, Closest&& closest) const {
    Agreement agreement;
    for (const Ray& world : rays) {
      const std::optional<GridRay> ray = grid_.quantise(world);
      if (!ray) continue;
      ++agreement.rays;
      classify(*ray, closest(*ray), agreement);
    }
    return agreement;
  }

  // Counts one ray already on the grid (a kind's set-up made it) with what a closest-hit search
  // found, as compare() does.
  void classifyRay(const GridRay& ray, const std::optional<KernelHit>& fixed,
                   Agreement& agreement) const {
    ++agreement.rays;
    classify(ray, fixed, agreement);
  }

  // The C99 kernel over every record, by brute force, the nearest kept as the listing keeps it.
  std::optional<KernelHit> c99Closest(const GridRay& ray) const {
    std::optional<KernelHit> best;
    int64_t tBest = kC99NoHitYet;
    for (const ProjectedTriangle& triangle : projected_.triangles) {
      const FixedTest test = c99Test(format_, ray, triangle, tBest);
      if (!test.hit()) continue;
      tBest = test.t;
      best = KernelHit{test.t, triangle.source};
    }
    return best;
  }

  // Whether the ray passes within the kernel's error of an edge of triangle `source`: its exact
  // barycentric margin is inside the bound of the header comment, so the kernel may decide either
  // way there, and a traversal pruning on exact boxes may decide the other.
  bool withinKernelError(const GridRay& ray, uint32_t source) const {
    const ProjectedTriangle* t = record(source);
    if (!t) return false;
    const ExactCrossing c = crossing(ray, *t);
    return std::abs(c.margin) <= c.marginBound;
  }

 private:
  Ray oracleRay(const GridRay& ray) const {
    const double unit = std::ldexp(1.0, -(format_.m - 1));
    return Ray{{double(ray.origin[0]), double(ray.origin[1]), double(ray.origin[2])},
               {ray.omega[0] * unit, ray.omega[1] * unit, ray.omega[2] * unit}};
  }

  const ProjectedTriangle* record(uint32_t source) const {
    for (const ProjectedTriangle& t : projected_.triangles)
      if (t.source == source) return &t;
    return nullptr;
  }

  ExactCrossing crossing(const GridRay& ray, const ProjectedTriangle& t) const {
    using Real = long double;
    const auto& x = gridVertices_;
    const auto& ids = held_.triangles[t.source];
    const uint32_t r = t.r, p = (r + 1) % 3, q = (r + 2) % 3;
    const GridPoint x0 = x[ids[0]], x1 = x[ids[1]], x2 = x[ids[2]];
    const Real e1[3] = {Real(x1[0] - x0[0]), Real(x1[1] - x0[1]), Real(x1[2] - x0[2])};
    const Real e2[3] = {Real(x2[0] - x0[0]), Real(x2[1] - x0[1]), Real(x2[2] - x0[2])};
    const Real nr = e1[p] * e2[q] - e1[q] * e2[p];
    const Real np = (e1[q] * e2[r] - e1[r] * e2[q]) / nr, nq = (e1[r] * e2[p] - e1[p] * e2[r]) / nr;
    const Real d = x0[r] + x0[p] * np + x0[q] * nq;
    const Real unit = std::ldexp(Real(1), -(format_.m - 1));
    const Real wr = ray.omega[r] * unit, wp = ray.omega[p] * unit, wq = ray.omega[q] * unit;
    const Real den = wr + wp * np + wq * nq;
    ExactCrossing c;
    c.t = double((d - ray.origin[r] - ray.origin[p] * np - ray.origin[q] * nq) / den);
    const Real kp = ray.origin[p] + c.t * wp - x0[p], kq = ray.origin[q] + c.t * wq - x0[q];
    const Real exact[4] = {e1[p] / nr, e1[q] / nr, e2[p] / nr, e2[q] / nr};
    const Real u = exact[0] * kq - exact[1] * kp, v = exact[3] * kp - exact[2] * kq;
    c.margin = double(std::min({u, v, 1 - u - v}));
    // The error bounds of the header comment.
    const Real m = std::ldexp(Real(1), -format_.m);
    const Real dnum = 1.5 + (ray.origin[p] + ray.origin[q]) * m;
    const Real dden = 4 * m + (std::abs(wp) + std::abs(wq)) * m;
    c.tBound = double((dnum + std::abs(c.t) * dden) / std::abs(den) + 1);
    const Real dk = c.tBound * std::max(std::abs(wp), std::abs(wq)) + 1;
    const Real edgeUnit = std::ldexp(Real(1), -(format_.m - 1 + format_.E));
    const int32_t codes[4] = {t.e1p, t.e1q, t.e2p, t.e2q};
    Real de[4];
    for (int i = 0; i < 4; ++i) de[i] = std::abs(codes[i] * edgeUnit - exact[i]);
    const Real du = de[0] * std::abs(kq) + de[1] * std::abs(kp) +
                    (std::abs(exact[0]) + std::abs(exact[1])) * dk;
    const Real dv = de[3] * std::abs(kp) + de[2] * std::abs(kq) +
                    (std::abs(exact[2]) + std::abs(exact[3])) * dk;
    c.marginBound = double(du + dv);
    return c;
  }

  bool clampedTriangle(const ProjectedTriangle& t) const {
    const int32_t highest = int32_t((int64_t(1) << (format_.m - 1)) - 1);
    for (int32_t e : {t.e1p, t.e1q, t.e2p, t.e2q})
      if (e == highest || e == -highest) return true;
    return false;
  }

  void classify(const GridRay& ray, const std::optional<KernelHit>& fixed, Agreement& a) const {
    const std::optional<OracleHit> oracle = closestHit(held_, oracleRay(ray), 0, INFINITY);
    if (fixed.has_value() == oracle.has_value() &&
        (!fixed || fixed->triangle == oracle->triangle)) {
      ++a.same;
      if (fixed) a.largestTError = std::max(a.largestTError, std::abs(fixed->t - oracle->t));
      return;
    }
    if (fixed && oracle &&
        std::abs(fixed->t - oracle->t) <= crossing(ray, *record(fixed->triangle)).tBound) {
      ++a.ties;
      return;
    }
    a.falseHits += fixed && !oracle;
    a.falseMisses += oracle && !fixed;
    a.otherTriangle += fixed && oracle;
    bool explained = false, clamped = false;
    for (const std::optional<uint32_t> source :
         {fixed ? std::optional<uint32_t>(fixed->triangle) : std::nullopt,
          oracle ? std::optional<uint32_t>(oracle->triangle) : std::nullopt}) {
      if (!source) continue;
      const ProjectedTriangle* t = record(*source);
      if (!t) continue;  // degenerate on the grid: the oracle cannot hit it either
      const ExactCrossing c = crossing(ray, *t);
      clamped = clamped || clampedTriangle(*t);
      explained = explained || std::abs(c.margin) <= c.marginBound || c.t < 1;
    }
    ++(explained ? a.explained : clamped ? a.clamped : a.unexplained);
  }

  FixedTriangleFormat format_;
  SceneGrid grid_;
  ProjectedMesh projected_;
  TriangleMesh held_;
  std::vector<GridPoint> gridVertices_;
};

}  // namespace rtu
