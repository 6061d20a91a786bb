#pragma once
// Seeded sampling of secondary and random rays (issue 32): one stream per (seed, stream number),
// so a pixel's samples do not depend on how many rays other pixels drew, and the same seed gives
// the same rays on every platform (splitmix64 and 53-bit doubles; no standard distribution, whose
// results the C++ standard leaves to each library).

#include <cstdint>

#include <glm/vec3.hpp>

namespace rtu {

class RaySampler {
 public:
  RaySampler(uint64_t seed, uint64_t stream);

  uint64_t next();
  // Uniform in [0, 1), 53 bits.
  double uniform();
  // A unit direction around `normal` (unit) with density cos(theta) / pi.
  glm::dvec3 cosineHemisphere(const glm::dvec3& normal);
  // A unit direction with uniform density on the sphere.
  glm::dvec3 uniformSphere();

 private:
  uint64_t state_;
};

}  // namespace rtu
