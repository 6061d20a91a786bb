#pragma once
// The picture of an animated scene's frame: each instance in its colour, lit by a sun and the
// sky, its voxel faces' normals taken back into the world through the instance's placement, over
// a sky gradient.

#include <string>
#include <vector>

#include "explore/animation_run.h"

namespace rtu {

// Three floats per pixel, rows from the top.
std::vector<float> shadeSceneFrame(const SceneFrame& frame, const SceneDescription& scene);

}  // namespace rtu
