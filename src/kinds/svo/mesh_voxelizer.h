#pragma once
// Surface voxelization of a triangle mesh: a voxel is solid when a triangle overlaps it
// (thesis toolchain: meshes become SVOs through this source and buildSvo).
//
// The mesh is first fitted into the root cube [-1,1]^3: scaled uniformly and centred on its
// bounding box so that its longest extent spans the cube minus one voxel on each side.
// Nothing dense is ever allocated: a node is classified by testing the triangles that overlap
// its parent, so memory stays O(depth x triangles) even at depth 12 (4096^3 voxels).

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/triangle_mesh.h"
#include "kinds/svo/voxel_source.h"

namespace rtu {

// Separating-axis test of Akenine-Möller ("Fast 3D Triangle-Box Overlap Testing", 2001). Closed
// sets: a triangle touching the box's boundary overlaps it, so a surface lying on a grid plane
// marks the voxels on both sides and leaves no hole.
bool triangleOverlapsBox(const std::array<glm::dvec3, 3>& triangle, const glm::dvec3& boxCentre,
                         const glm::dvec3& boxHalfSize);

class MeshVoxelizer : public VoxelSource {
 public:
  // Throws std::invalid_argument if depth is not in [2, kMaxSvoDepth] (below 2 the one-voxel
  // margin leaves no room), the mesh has no triangle, an index is out of range, a vertex is not
  // finite or the triangles' vertices all coincide.
  MeshVoxelizer(const TriangleMesh& mesh, int depth);

  int depth() const override { return depth_; }

  // Empty when no triangle overlaps the node, Full for an overlapped voxel, Mixed otherwise.
  // Keeps a cache of the last node classified per level: not safe to call from several threads.
  // Throws std::invalid_argument for a level outside 0 to depth().
  Occupancy classify(const OctreeNode& node) const override;

  // The fitting transform: a mesh point p lies at p * scale() + offset() in the root cube.
  const glm::dvec3& offset() const { return offset_; }
  double scale() const { return scale_; }
  size_t triangleCount() const { return triangles_.size(); }

 private:
  struct FittedTriangle {
    std::array<glm::dvec3, 3> vertices;
    glm::dvec3 lower, upper;  // bounding box, a cheap rejection before the full test
  };
  // The triangles overlapping the last node classified at one level.
  struct LevelCache {
    OctreeNode node{-1};  // level -1: nothing cached yet
    std::vector<uint32_t> triangles;
  };

  bool overlaps(uint32_t triangleIndex, const glm::dvec3& lower, const glm::dvec3& upper) const;
  // Triangles that may overlap `node`: its parent's (all for the root).
  const std::vector<uint32_t>& candidatesFor(const OctreeNode& node) const;
  // Triangles that overlap `node`, from the cache or computed into it.
  const std::vector<uint32_t>& overlappingTriangles(const OctreeNode& node) const;

  int depth_;
  glm::dvec3 offset_;
  double scale_;
  std::vector<FittedTriangle> triangles_;
  std::vector<uint32_t> allTriangles_;
  mutable std::vector<LevelCache> cache_;  // one per level above the voxels
};

}  // namespace rtu
