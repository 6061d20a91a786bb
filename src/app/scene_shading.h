#pragma once
// The picture of an animated scene's frame: each instance in its colour, lit by a sun and the
// sky, its voxel faces' normals taken back into the world through the instance's placement, over
// a sky gradient.

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "explore/animation_run.h"

namespace rtu {

// The sky seen along a primary ray's `direction`.
glm::dvec3 sceneSky(const glm::dvec3& direction);
// A surface of `colour` whose unit world normal, facing the ray, is `normal`, lit by the sun and
// the sky: every core kind's animated frames are shaded by these two.
glm::dvec3 shadeSceneSurface(const glm::dvec3& colour, const glm::dvec3& normal);

// Three floats per pixel, rows from the top.
std::vector<float> shadeSceneFrame(const SceneFrame& frame, const SceneDescription& scene);

}  // namespace rtu
