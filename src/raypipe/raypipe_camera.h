#pragma once
// The seed's camera registers (RaypipeCamera: E, U, V, W in hardware space, R1 CAMERA/*) from
// rtusim's camera (inputs/camera.h: position, look-at point, up, vertical field of view), and the
// registers a run takes: each given one (raypipe.camera.eye, .u, .v, .w) or else the converted.
//
// The conversion: E = the position, U = the unit right vector, V = the unit true up and
// W = the unit forward vector over tan(fov / 2), each with x and y swapped (hardware space,
// specs/001 §4.6), rounded to binary32. The PRG's direction at pixel (x, y_prg) is then
// U (x pw - 320) + V (y_prg pw - 240) + 240 W, so the field of view is carried by W's length:
// 90 degrees for |W| = 1, as the seed's reset camera has it. Its centre ray (x = cols / 2,
// y_prg = rows / 2) is 240 W, toward the look-at point; it samples each pixel at its lower-left
// corner, where rtusim's camera samples its centre.

#include <array>
#include <optional>

#include "inputs/camera.h"
#include "raypipe/raypipe_config.h"

namespace rtu {

// Throws std::invalid_argument as Camera::validate does for a camera that makes no rays.
RaypipeCamera raypipeCameraOf(const Camera& camera);

// rtusim's camera nearest the registers (the inverse of raypipeCameraOf, exact up to rounding
// when U, V and W are orthogonal and U, V of one length), for a frame of width x height: what the
// images that shade by rtusim's camera (the surface turned to the viewer) take.
Camera cameraOfRegisters(const RaypipeCamera& registers, int width, int height);

// The registers a run sets; an unset one is converted from rtusim's camera.
struct RaypipeCameraSettings {
  std::optional<std::array<float, 3>> eye, u, v, w;

  RaypipeCamera resolve(const Camera& camera) const;
};

}  // namespace rtu
