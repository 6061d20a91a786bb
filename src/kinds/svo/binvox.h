#pragma once
// Voxel grids in the .binvox format of Patrick Min's binvox voxelizer (used by the thesis
// toolchain). A file is an ASCII header
//   #binvox 1
//   dim D D D            depth, height, width: only cubic grids are accepted, 1 <= D <= 4096
//   translate tx ty tz   optional: where the voxelized model came from (kept for reports)
//   scale s              optional: likewise
//   data
// followed by run-length pairs of bytes (value 0 or 1, count 0 to 255) that cover the D^3 voxels
// in binvox order: index = x * D * D + z * D + y, so y runs fastest, then z, then x. binvox's y is
// up, as is the octree's: binvox voxel (x, y, z) becomes octree voxel (x, y, z).

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "kinds/svo/voxel_source.h"

namespace rtu {

constexpr int kMaxBinvoxDim = 4096;

// A binvox grid padded with empty voxels up to 2^depth voxels per axis, depth = ceil(log2 D)
// (at least 1). Holds one bit per voxel plus, for every node above the voxels, whether it holds
// any solid voxel and whether all of its voxels are: classify is O(1) at every level.
class BinvoxGrid : public VoxelSource {
 public:
  // Throws std::runtime_error naming `path` and the problem: unreadable file, bad magic or
  // version, missing or malformed dim line, non-cubic or out-of-range dimensions, no 'data' line,
  // run values other than 0 or 1, runs covering more or fewer than D^3 voxels, truncated data.
  // The data is checked before the grid is allocated.
  explicit BinvoxGrid(const std::string& path);

  int depth() const override { return depth_; }
  // Throws std::invalid_argument for a node outside the grid's levels or cells.
  Occupancy classify(const OctreeNode& node) const override;

  int dim() const { return dim_; }
  uint64_t solidVoxels() const { return solidVoxels_; }
  // binvox's record of how the model was normalised into the grid (identity when absent).
  const glm::dvec3& translate() const { return translate_; }
  double scale() const { return scale_; }

 private:
  bool allSolid(int level, uint64_t index) const;
  void buildSummaries();

  int dim_ = 0;
  int depth_ = 0;
  glm::dvec3 translate_{0.0};
  double scale_ = 1.0;
  uint64_t solidVoxels_ = 0;
  // Per level 0..depth, whether a node holds any solid voxel; level depth is the grid itself.
  std::vector<std::vector<bool>> anySolid_;
  // Per level 0..depth-1, whether every voxel of a node is solid.
  std::vector<std::vector<bool>> allSolid_;
};

// Writes a D^3 binvox file (identity translate and scale) where voxel (x, y, z) is solid when
// `solid(x, y, z)`. Throws std::invalid_argument for a dim outside 1 to kMaxBinvoxDim and
// std::runtime_error naming `path` when it cannot be written.
void writeBinvox(const std::string& path, int dim, const std::function<bool(int, int, int)>& solid);

}  // namespace rtu
