#pragma once
// The BVH core's primitive intersectors, the traversal's third template parameter (issue 27:
// "Moller-Trumbore and a watertight test as the triangle test choices"; seed 003 names none).
// Each prepares what it needs once per ray and then tests triangles in float32, with the
// conventions of geometry/triangle_tests.h.

#include <cstdint>
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

// Either test, chosen per core from the settings (BvhConfig::triangleTest) rather than at compile
// time, so that one registered kind offers both: one branch per triangle test, the same for every
// test of a run (well predicted), no virtual call. bench/triangle_bench measures it against the
// templated forms (docs/performance.md).
enum class TriangleTest : uint8_t { Watertight, MollerTrumbore };

class SelectedIntersector {
 public:
  SelectedIntersector() = default;
  explicit SelectedIntersector(TriangleTest test) : test_(test) {}

  void prepare(const BvhRay& ray) {
    if (test_ == TriangleTest::Watertight) watertight_.prepare(ray);
  }
  // Flattened: with both tests in one function GCC inlined neither, and the run-time choice cost
  // 19-26 % of the golden traversal's time against a test fixed at compile time.
  [[gnu::flatten]] std::optional<TriangleHit<float>> intersect(const BvhRay& ray,
                                                               const Vec3<float>& v0,
                                                               const Vec3<float>& v1,
                                                               const Vec3<float>& v2, float tMin,
                                                               float tMax) const {
    if (test_ == TriangleTest::Watertight)
      return watertight_.intersect(ray, v0, v1, v2, tMin, tMax);
    return MollerTrumboreIntersector{}.intersect(ray, v0, v1, v2, tMin, tMax);
  }

 private:
  TriangleTest test_ = TriangleTest::Watertight;
  WatertightIntersector watertight_;
};

}  // namespace rtu
