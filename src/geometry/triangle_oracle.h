#pragma once
// The independent geometric oracle of the triangle kinds (docs/architecture.md, "Independent
// oracles"): the closest hit of a ray over every triangle of a mesh, by the float64 watertight test
// of triangle_tests.h. It knows no node, stack or memory layout, so it shares no traversal code
// with any kind; a kind's traversal is checked against it on the geometry the kind's format holds.

#include <cstdint>
#include <optional>

#include "geometry/ray.h"
#include "geometry/triangle_mesh.h"

namespace rtu {

struct OracleHit {
  double t = 0, u = 0, v = 0;  // t along the ray's direction; barycentrics as triangle_tests.h
  uint32_t triangle = 0;       // index into the mesh's triangles
};

// The nearest hit with t in [tMin, tMax]; of hits at the same t, the lowest triangle index.
std::optional<OracleHit> closestHit(const TriangleMesh& mesh, const Ray& ray, double tMin,
                                    double tMax);

}  // namespace rtu
