#include "raypipe/raypipe_camera.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "kinds/kd/trayracer_scene.h"

namespace rtu {
namespace {

std::array<float, 3> hardwareFloats(const glm::dvec3& world) {
  const glm::dvec3 hardware = toHardwareSpace(world);
  return {static_cast<float>(hardware.x), static_cast<float>(hardware.y),
          static_cast<float>(hardware.z)};
}

glm::dvec3 worldOf(const std::array<float, 3>& hardware) {
  return toHardwareSpace(glm::dvec3(hardware[0], hardware[1], hardware[2]));  // its own inverse
}

}  // namespace

RaypipeCamera raypipeCameraOf(const Camera& camera) {
  camera.validate();
  const glm::dvec3 forward = glm::normalize(camera.lookAt - camera.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::dvec3 trueUp = glm::cross(right, forward);
  const double screen = 1.0 / std::tan(camera.verticalFovDegrees * M_PI / 360.0);
  return RaypipeCamera{hardwareFloats(camera.position), hardwareFloats(right),
                       hardwareFloats(trueUp), hardwareFloats(forward * screen)};
}

Camera cameraOfRegisters(const RaypipeCamera& registers, int width, int height) {
  Camera camera;
  camera.position = worldOf(registers.eye);
  camera.lookAt = camera.position + worldOf(registers.w);
  camera.up = worldOf(registers.v);
  camera.verticalFovDegrees =
      2 * std::atan(glm::length(camera.up) / glm::length(worldOf(registers.w))) * 180 / M_PI;
  camera.width = width;
  camera.height = height;
  return camera;
}

RaypipeCamera RaypipeCameraSettings::resolve(const Camera& camera) const {
  // rtusim's camera is read (and checked) only when a register is left to it.
  const RaypipeCamera converted = eye && u && v && w ? RaypipeCamera{} : raypipeCameraOf(camera);
  return RaypipeCamera{eye.value_or(converted.eye), u.value_or(converted.u),
                       v.value_or(converted.v), w.value_or(converted.w)};
}

}  // namespace rtu
