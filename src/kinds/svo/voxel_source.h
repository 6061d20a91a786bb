#pragma once
// Anything that can say which voxels of a 2^depth grid over the root cube [-1,1]^3 are solid.
// The SVO builder asks about whole octree nodes so that sources which know large uniform regions
// (an analytic sphere, a height field) answer in one call instead of voxel by voxel.

#include <cstdint>

#include <glm/vec3.hpp>

namespace rtu {

enum class Occupancy : uint8_t { Empty, Full, Mixed };

// An octree node: at `level` (0 = the root cube) the cube is split into 2^level cells per axis
// and the node is cell (x, y, z), each in [0, 2^level). Slot bit k of a child means the upper
// half along axis k (bit 0 x, bit 1 y, bit 2 z).
struct OctreeNode {
  int level = 0;
  uint32_t x = 0, y = 0, z = 0;

  OctreeNode child(int slot) const {
    return {level + 1, 2 * x + (slot & 1), 2 * y + (slot >> 1 & 1), 2 * z + (slot >> 2 & 1)};
  }
  OctreeNode parent() const { return {level - 1, x >> 1, y >> 1, z >> 1}; }  // level > 0
  double size() const { return 2.0 / static_cast<double>(1u << level); }     // edge length
  glm::dvec3 lower() const { return glm::dvec3(x, y, z) * size() - 1.0; }
  glm::dvec3 upper() const { return lower() + size(); }
  glm::dvec3 centre() const { return lower() + 0.5 * size(); }
};

class VoxelSource {
 public:
  virtual ~VoxelSource() = default;

  // Voxels are the nodes at this level: the grid has 2^depth voxels per axis.
  virtual int depth() const = 0;

  // Whether every voxel inside `node` is empty, every one is solid, or it is not known.
  // Must not answer Mixed at level == depth(). Mixed is always a safe answer above it: the builder
  // then asks about the children and merges uniform results itself.
  virtual Occupancy classify(const OctreeNode& node) const = 0;
};

}  // namespace rtu
