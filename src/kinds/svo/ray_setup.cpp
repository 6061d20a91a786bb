#include "kinds/svo/ray_setup.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rtu {

namespace {

// Throws std::invalid_argument for a NaN or infinite component or a zero direction: their
// t-values would be NaN, which the conversion turns into a silent answer.
void checkRay(const Ray& ray) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(ray.origin[k]) || !std::isfinite(ray.direction[k]))
      throw std::invalid_argument("ray origin and direction must be finite numbers");
  if (ray.direction == glm::dvec3(0.0)) throw std::invalid_argument("ray direction is zero");
}

// The direction scaled by a power of two so that its largest component lies in [0.5, 1): exact,
// so the normalised direction is unchanged, but the squares below neither underflow (all
// components tiny) nor overflow (all huge) in float.
glm::dvec3 scaledDirection(const glm::dvec3& direction) {
  int exponent = 0;
  std::frexp(std::max({std::abs(direction.x), std::abs(direction.y), std::abs(direction.z)}),
             &exponent);
  return direction * std::ldexp(1.0, -exponent);
}

}  // namespace

template <class Real>
RayParameters<Real> computeRayParameters(const Ray& ray, Real epsilon) {
  checkRay(ray);
  const glm::dvec3 scaled = scaledDirection(ray.direction);
  std::array<Real, 3> origin{};
  std::array<Real, 3> direction{};
  for (int k = 0; k < 3; ++k) {
    origin[k] = static_cast<Real>(ray.origin[k]);
    direction[k] = static_cast<Real>(scaled[k]);
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

TValueRecord makeTValueRecord(uint32_t id, const Ray& ray, uint32_t root, double epsilon) {
  const RayParameters<float> parameters =
      computeRayParameters<float>(ray, static_cast<float>(epsilon));
  TValueRecord job;
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
