#pragma once
// The linear BVH builder (Lauterbach et al. 2009; Karras 2012's split rule): each triangle's box
// centre quantised to 10 bits per axis within the centres' box and interleaved into a 30-bit
// Morton code (x in the highest bit of each triple), the references sorted by code (ties by
// triangle index), then top down: a node of at most maxLeafSize references is a leaf; otherwise
// it divides where its first and last codes' highest differing bit turns from 0 to 1, or, when
// they share one code, in half (counted). The fastest builder and the poorest trees: what a GPU
// builds per frame.

#include <cstdint>

#include "geometry/triangle_mesh.h"
#include "kinds/bvh/build_primitives.h"
#include "kinds/bvh/build_tree.h"

namespace rtu {

struct LbvhConfig {
  uint32_t maxLeafSize = 4;
};

struct LbvhBuild {
  BuildTree tree;
  uint32_t equalCodeSplits = 0;
};

// The 30-bit Morton code of a point quantised to 10 bits per axis: x's bits at 29, 26, ..., y's
// at 28, 25, ..., z's at 27, 24, ...
uint32_t mortonCode(uint32_t x, uint32_t y, uint32_t z);

// Throws std::invalid_argument for primitives checkPrimitives refuses or a maximum leaf size of 0.
LbvhBuild buildLbvh(const BuildPrimitives& primitives, const LbvhConfig& config = {});
// Over the mesh's triangles; also throws for a mesh buildPrimitives refuses.
LbvhBuild buildLbvh(const TriangleMesh& mesh, const LbvhConfig& config = {});

}  // namespace rtu
