#pragma once
// A ray as the BVH core traverses it: float32 origin and direction in the mesh's space (or the
// world's, for a two-level BVH's top level), the reciprocal direction its slab tests multiply by,
// and its t range. Built once per job (the job manager's set-up), so the traversal never divides.

#include <algorithm>
#include <cmath>

#include "geometry/aabb.h"
#include "geometry/triangle_tests.h"

namespace rtu {

struct BvhRay {
  Vec3<float> origin{0.0f}, direction{0.0f, 0.0f, 1.0f};
  Vec3<float> inverse{0.0f};  // 1 / direction, with tiny components replaced (makeBvhRay)
  float tMin = 0.0f, tMax = 0.0f;
};

// The ray with its reciprocal direction. A direction component below 2^-64 in magnitude is taken
// as 2^-64 with its sign (+0 as positive) before the division, so a slab test never computes
// 0 * infinity: a box's slab distances on that axis are then huge, never NaN.
inline BvhRay makeBvhRay(const Vec3<float>& origin, const Vec3<float>& direction, float tMin,
                         float tMax) {
  constexpr float kTiny = 0x1.0p-64f;
  BvhRay ray{origin, direction, Vec3<float>(0.0f), tMin, tMax};
  for (int k = 0; k < 3; ++k) {
    const float d = std::abs(direction[k]) < kTiny ? std::copysign(kTiny, direction[k])
                                                   : direction[k];
    ray.inverse[k] = 1.0f / d;
  }
  return ray;
}

struct BoxHit {
  bool hit = false;
  float tEntry = 0;  // where the ray enters the box (within [tMin, tMax] when hit)
};

// The float32 slab test against [tMin, tMax]: each distance one rounded product, no fused
// multiply-add; entry max(tMin, the per-axis nears), exit min(tMax, the fars), a hit when the entry
// is not beyond the exit.
inline BoxHit slabTest(const BvhRay& ray, const Aabb<float>& box, float tMin, float tMax) {
  float tNear = tMin, tFar = tMax;
  for (int k = 0; k < 3; ++k) {
    const float lower = box.lower[k] - ray.origin[k];
    const float upper = box.upper[k] - ray.origin[k];
    const float t0 = lower * ray.inverse[k], t1 = upper * ray.inverse[k];
    tNear = std::max(tNear, std::min(t0, t1));
    tFar = std::min(tFar, std::max(t0, t1));
  }
  return BoxHit{tNear <= tFar, tNear};
}

}  // namespace rtu
