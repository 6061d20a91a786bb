#include "rtu/ray_record.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

namespace rtu {

namespace {

void checkComponents(const std::array<float, 3>& v, const std::string& what) {
  const char* const axes[] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k) {
    const std::string field = what + " " + axes[k];
    if (!std::isfinite(v[k])) throw std::runtime_error(field + " is not a finite number");
    if (std::abs(v[k]) > kMaxModelCoordinate) throw std::runtime_error(field + " is beyond 2^64");
  }
}

}  // namespace

void RayRecord::validate() const {
  if (id > kMaxRayId) {
    char word[16];
    std::snprintf(word, sizeof word, "0x%08x", id);
    throw std::runtime_error(std::string("job word ") + word +
                             ": bits 31:28 are the span (31:30) and zero (29:28), "
                             "and bits 29:28 are set (ids have 28 bits)");
  }
  checkComponents(origin, "origin");
  checkComponents(direction, "direction");
  if (direction[0] == 0.0f && direction[1] == 0.0f && direction[2] == 0.0f)
    throw std::runtime_error("direction is zero");
}

uint32_t RayRecord::idWord() const {
  return id | (span == RaySpan::AnyHit ? kAnyHitBit : 0u) |
         (span == RaySpan::Ahead ? kAheadBit : 0u);
}

RayRecord recordOfWord0(uint32_t word) {
  if ((word & kAnyHitBit) && (word & kAheadBit))
    throw std::runtime_error("bits 31 (any-hit) and 30 (ahead) of the first word are both set");
  RayRecord record;
  record.span = word & kAnyHitBit  ? RaySpan::AnyHit
                : word & kAheadBit ? RaySpan::Ahead
                                   : RaySpan::Line;
  record.id = word & ~(kAnyHitBit | kAheadBit);
  return record;
}

RayRecord makeRayRecord(uint32_t id, const Ray& ray, uint32_t modelAddress) {
  const glm::dvec3 direction = glm::normalize(ray.direction);
  RayRecord record;
  record.id = id;
  record.modelAddress = modelAddress;
  for (int k = 0; k < 3; ++k) {
    record.origin[k] = static_cast<float>(ray.origin[k]);
    record.direction[k] = static_cast<float>(direction[k]);
  }
  return record;
}

}  // namespace rtu
