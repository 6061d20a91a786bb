#include "inputs/keyframes.h"

#include <glm/gtc/quaternion.hpp>

namespace rtu {

glm::dvec3 lerpVector(const glm::dvec3& a, const glm::dvec3& b, double fraction) {
  return a + (b - a) * fraction;
}

glm::dquat slerpShorter(const glm::dquat& a, const glm::dquat& b, double fraction) {
  const glm::dquat target = glm::dot(a, b) < 0.0 ? -b : b;
  return glm::normalize(glm::slerp(a, target, fraction));
}

ModelPlacement PlacementTracks::at(double time) const {
  ModelPlacement placement;
  placement.translation = translation.at(time, lerpVector, glm::dvec3(0.0));
  placement.rotation =
      glm::mat3_cast(rotation.at(time, slerpShorter, glm::dquat(1.0, 0.0, 0.0, 0.0)));
  placement.scale = scale.at(time, lerpVector, glm::dvec3(1.0));
  return placement;
}

glm::dquat quaternionFromEulerDegrees(const glm::dvec3& degrees) {
  return glm::normalize(glm::quat_cast(rotationFromEulerDegrees(degrees)));
}

}  // namespace rtu
