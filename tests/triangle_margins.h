#pragma once
// How close a ray's line passes to a triangle's edges: what the BVH oracle checks
// (test_bvh_oracle.cpp, test_two_level_oracle.cpp) weigh a disagreement by.

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/ray.h"
#include "geometry/triangle_mesh.h"

namespace rtu {

// The distance between the ray's line and the nearest of the triangle's edges (segments), in
// world units: what float32 arithmetic must resolve to decide whether the ray passes inside. A
// ray grazing the triangle's plane passes close to the edges it crosses, so this covers grazing
// rays too.
inline double edgeMargin(const TriangleMesh& mesh, uint32_t triangle, const Ray& ray) {
  const glm::dvec3 d = glm::normalize(ray.direction);
  double nearest = INFINITY;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 a = mesh.vertices[mesh.triangles[triangle][i]];
    const glm::dvec3 b = mesh.vertices[mesh.triangles[triangle][(i + 1) % 3]];
    // |(a + s (b - a) - origin) x d| over s in [0, 1]: a quadratic in s.
    const glm::dvec3 c0 = glm::cross(a - ray.origin, d), c1 = glm::cross(b - a, d);
    const double square = glm::dot(c1, c1);
    const double s = square > 0 ? std::clamp(-glm::dot(c0, c1) / square, 0.0, 1.0) : 0.0;
    nearest = std::min(nearest, glm::length(c0 + s * c1));
  }
  return nearest;
}

inline double largestCoordinate(const glm::dvec3& p) {
  return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
}

}  // namespace rtu
