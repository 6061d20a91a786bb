#pragma once
// A ray in double precision, as cameras and scene generators make it: the start of every kind's
// rays before a host record rounds it to the hardware's formats.

#include <glm/vec3.hpp>

namespace rtu {

struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, 1.0};
};

}  // namespace rtu
