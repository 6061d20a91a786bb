#include "ray_setup.h"

#include <cmath>
#include <cstring>

namespace rtu {

template <class Real>
RayParameters<Real> computeRayParameters(const Ray& ray, Real epsilon) {
  std::array<Real, 3> origin{};
  std::array<Real, 3> direction{};
  for (int k = 0; k < 3; ++k) {
    origin[k] = static_cast<Real>(ray.origin[k]);
    direction[k] = static_cast<Real>(ray.direction[k]);
  }
  const Real length = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] +
                                direction[2] * direction[2]);
  RayParameters<Real> parameters;
  for (int k = 0; k < 3; ++k) {
    Real d = direction[k] / length;
    Real o = origin[k];
    if (d == Real(0)) d = epsilon;
    if (d < Real(0)) {
      d = -d;
      o = -o;
      parameters.a |= static_cast<uint8_t>(1u << k);
    }
    parameters.t0[k] = (Real(-1) - o) / d;
    parameters.t1[k] = (Real(1) - o) / d;
  }
  return parameters;
}

template RayParameters<float> computeRayParameters(const Ray&, float);
template RayParameters<double> computeRayParameters(const Ray&, double);

uint32_t floatBits(float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

float bitsToFloat(uint32_t bits) {
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

TraversalJob makeTraversalJob(uint32_t id, const Ray& ray, uint32_t root, double epsilon) {
  const RayParameters<float> parameters =
      computeRayParameters<float>(ray, static_cast<float>(epsilon));
  TraversalJob job;
  job.id = id;
  job.a = parameters.a;
  job.root = root;
  for (int k = 0; k < 3; ++k) {
    job.t0Bits[k] = floatBits(parameters.t0[k]);
    job.t1Bits[k] = floatBits(parameters.t1[k]);
  }
  return job;
}

}  // namespace rtu
