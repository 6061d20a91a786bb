#pragma once
// Shadow rays' lights (issue 32, docs/workloads.md): a point light, or an area light (a
// rectangle or a disc) whose points a hit's shadow rays sample with the seeded sampler
// (inputs/ray_sampler.h), `SecondarySettings::lightSamples` of them per hit.

#include <string>

#include <glm/vec3.hpp>

#include "inputs/ray_sampler.h"

namespace rtu {

struct Light {
  enum class Shape { Point, Rectangle, Disc };
  Shape shape = Shape::Point;
  glm::dvec3 position{0.0};  // the point; a rectangle's or disc's centre
  glm::dvec3 edgeU{0.0};     // rectangle: its two edges, full lengths: centre + (a - 1/2) edgeU
  glm::dvec3 edgeV{0.0};     //   + (b - 1/2) edgeV for a, b in [0, 1)
  glm::dvec3 normal{0.0};    // disc: its axis, unit
  double radius = 0;         // disc

  static Light point(const glm::dvec3& at) { return {Shape::Point, at}; }
  bool isArea() const { return shape != Shape::Point; }
  // A point uniform over the light (the point light's position, drawing nothing).
  glm::dvec3 sample(RaySampler& sampler) const;
};

// "point", "rect", "disc".
const char* toString(Light::Shape shape);

// A light as text (docs/workloads.md): "x,y,z" (a point), "rect:cx,cy,cz:ux,uy,uz:vx,vy,vz"
// (a rectangle: centre and edges), "disc:cx,cy,cz:nx,ny,nz:r" (a disc: centre, axis, radius).
// Throws std::invalid_argument naming `option`: edges parallel or zero, an axis of length zero, a
// radius not positive, a number not finite.
Light parseLight(const std::string& text, const std::string& option);

}  // namespace rtu
