#pragma once
// First phase of the traversal algorithm (thesis section 6.2.1): from a ray in model space to the
// direction coefficient a and the t-parameters against the root cube [-1,1]^3.

#include <array>
#include <cstdint>

#include <glm/vec3.hpp>

#include "base/float_bits.h"
#include "geometry/ray.h"
#include "kinds/svo/thesis_records.h"

namespace rtu {

// Replaces exact zero direction components after normalisation (project thesis trick, 4.1.3).
constexpr double kDefaultDirectionEpsilon = 1e-4;

template <class Real>
struct RayParameters {
  uint8_t a = 0;  // bit k set when direction component k was negative and has been mirrored
  std::array<Real, 3> t0{};
  std::array<Real, 3> t1{};
};

// Normalises the direction, replaces exact zeros with `epsilon`, mirrors negative components
// around the cube centre and computes t0 = (-1 - o) / d and t1 = (1 - o) / d, all in `Real`
// arithmetic: float for the hardware job, double for the float64 reference.
// a is the OR of the sign bits (the printed driver's `a = 2**comp` loses all but the last one).
// The direction is first scaled by a power of two (exact), so tiny or huge components neither
// underflow nor overflow. Throws std::invalid_argument for a NaN or infinite component or a zero
// direction.
template <class Real>
RayParameters<Real> computeRayParameters(const Ray& ray, Real epsilon);

// The float32 job the thesis driver would send for `ray` (appendix F, get_ray_job).
TValueRecord makeTValueRecord(uint32_t id, const Ray& ray, uint32_t root,
                              double epsilon = kDefaultDirectionEpsilon);

}  // namespace rtu
