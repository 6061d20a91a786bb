#pragma once
// The BVH core's primitive intersectors, the traversal's third template parameter (issue 27:
// "Moller-Trumbore and a watertight test as the triangle test choices"; seed 003 names none).
// Each prepares what it needs once per ray and then tests triangles in float32, with the
// conventions of geometry/triangle_tests.h.

#include <optional>

#include "geometry/triangle_tests.h"
#include "kinds/bvh/bvh_ray.h"

namespace rtu {

// Woop, Benthin and Wald 2013: the ray sheared once per job.
class WatertightIntersector {
 public:
  static constexpr const char* kName = "watertight";
  void prepare(const BvhRay& ray) { sheared_ = ShearedRay<float>(ray.origin, ray.direction); }
  std::optional<TriangleHit<float>> intersect(const BvhRay&, const Vec3<float>& v0,
                                              const Vec3<float>& v1, const Vec3<float>& v2,
                                              float tMin, float tMax) const {
    return watertight(sheared_, v0, v1, v2, tMin, tMax);
  }

 private:
  ShearedRay<float> sheared_{Vec3<float>(0.0f), Vec3<float>(0.0f, 0.0f, 1.0f)};
};

// Moller and Trumbore 1997, nothing to prepare.
struct MollerTrumboreIntersector {
  static constexpr const char* kName = "moller-trumbore";
  void prepare(const BvhRay&) {}
  std::optional<TriangleHit<float>> intersect(const BvhRay& ray, const Vec3<float>& v0,
                                              const Vec3<float>& v1, const Vec3<float>& v2,
                                              float tMin, float tMax) const {
    return mollerTrumbore(ray.origin, ray.direction, v0, v1, v2, tMin, tMax);
  }
};

}  // namespace rtu
