#pragma once
// A ray as the BVH core traverses it: float32 origin and direction in the mesh's space, the
// reciprocal direction its slab tests multiply by, and its t range. Built once per job (the job
// manager's set-up), so the traversal never divides.

#include <cmath>

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

}  // namespace rtu
