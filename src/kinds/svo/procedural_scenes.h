#pragma once
// Built-in voxel scenes over the root cube [-1,1]^3, for tests, benchmarks and renders without
// input files. A voxel is solid when its centre is inside the shape (see docs/inputs-scenes.md):
//   sphere   radius 0.8 at the origin
//   shell    hollow sphere, outer radius 0.8, wall max(0.1, two voxels) thick
//   menger   Menger sponge filling the whole cube, as many iterations as 2^depth voxels resolve
//   terrain  solid below a seeded fractal value-noise height field over x/z, y up
//   noise    each voxel solid with probability 1/32, from a hash of (x, y, z, seed)
//   room     a room with furniture, open at z = -1 (--camera 0,0.3,-1.1 --look-at 0,-0.45,0.6)
// The seed only changes terrain and noise. Each scene answers whole octree nodes Empty or Full
// where it can tell cheaply and never wrongly; see VoxelSource.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "kinds/svo/voxel_source.h"

namespace rtu {

// Throws std::invalid_argument for an unknown name (listing the known ones) or a depth outside
// [1, 16].
std::unique_ptr<VoxelSource> makeProceduralScene(const std::string& name, int depth,
                                                 uint64_t seed = 1);

const std::vector<std::string>& proceduralSceneNames();

}  // namespace rtu
