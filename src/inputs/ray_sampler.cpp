#include "inputs/ray_sampler.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace rtu {

namespace {

constexpr double kTwoPi = 6.283185307179586476925;

uint64_t splitmix64(uint64_t& state) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

RaySampler::RaySampler(uint64_t seed, uint64_t stream) : state_(seed) {
  uint64_t streamState = stream;
  state_ ^= splitmix64(streamState);
}

uint64_t RaySampler::next() { return splitmix64(state_); }

double RaySampler::uniform() { return static_cast<double>(next() >> 11) * 0x1p-53; }

// Malley's method: a uniform point on the unit disc lifted onto the hemisphere, in the
// orthonormal basis of Duff et al. (2017) around the normal.
glm::dvec3 RaySampler::cosineHemisphere(const glm::dvec3& normal) {
  const double r = std::sqrt(uniform());
  const double phi = kTwoPi * uniform();
  const double x = r * std::cos(phi), y = r * std::sin(phi);
  const double z = std::sqrt(std::max(0.0, 1.0 - x * x - y * y));
  const double sign = std::copysign(1.0, normal.z);
  const double a = -1.0 / (sign + normal.z);
  const double b = normal.x * normal.y * a;
  const glm::dvec3 tangent{1.0 + sign * normal.x * normal.x * a, sign * b, -sign * normal.x};
  const glm::dvec3 bitangent{b, sign + normal.y * normal.y * a, -normal.y};
  return glm::normalize(x * tangent + y * bitangent + z * normal);
}

glm::dvec3 RaySampler::uniformSphere() {
  const double z = 1.0 - 2.0 * uniform();
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = kTwoPi * uniform();
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace rtu
