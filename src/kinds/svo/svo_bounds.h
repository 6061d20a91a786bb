#pragma once
// The box around every solid voxel of an SVO image, in model space (the root cube [-1,1]^3):
// what a bounding sphere of an instance is drawn around.

#include <glm/vec3.hpp>

#include "kinds/svo/svo_image.h"

namespace rtu {

struct VoxelBounds {
  bool empty = true;  // no solid voxel at all
  glm::dvec3 lower{0.0};
  glm::dvec3 upper{0.0};
};

// Walks the tree from the image's root; the image must be valid (svo_validator.h).
VoxelBounds solidVoxelBounds(const SvoImage& image);

}  // namespace rtu
