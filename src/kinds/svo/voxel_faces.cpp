#include "kinds/svo/voxel_faces.h"

#include <array>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace rtu {
namespace {

// Which voxels are solid, one bit each, found by descending the source's octree: an Empty node is
// skipped and a Full one marked whole, so only mixed regions are asked voxel by voxel.
class Occupied {
 public:
  explicit Occupied(const VoxelSource& source)
      : cells_(1u << source.depth()), bits_(size_t{cells_} * cells_ * cells_) {
    mark(source, OctreeNode{});
  }
  uint32_t cells() const { return cells_; }
  // Outside the grid counts as empty.
  bool solid(int64_t x, int64_t y, int64_t z) const {
    if (x < 0 || y < 0 || z < 0 || x >= cells_ || y >= cells_ || z >= cells_) return false;
    return bits_[index(x, y, z)];
  }

 private:
  size_t index(int64_t x, int64_t y, int64_t z) const {
    return (static_cast<size_t>(z) * cells_ + y) * cells_ + x;
  }
  void mark(const VoxelSource& source, const OctreeNode& node) {
    const Occupancy occupancy = source.classify(node);
    if (occupancy == Occupancy::Empty) return;
    if (occupancy == Occupancy::Mixed) {
      for (int slot = 0; slot < 8; ++slot) mark(source, node.child(slot));
      return;
    }
    const uint32_t span = cells_ >> node.level;  // voxels per axis inside the node
    for (uint32_t z = node.z * span; z < (node.z + 1) * span; ++z)
      for (uint32_t y = node.y * span; y < (node.y + 1) * span; ++y)
        for (uint32_t x = node.x * span; x < (node.x + 1) * span; ++x) bits_[index(x, y, z)] = true;
  }

  uint32_t cells_;
  std::vector<bool> bits_;
};

// Builds the mesh, sharing a vertex per grid point.
class FaceMesh {
 public:
  explicit FaceMesh(uint32_t cells) : cells_(cells), size_(2.0 / cells) {}

  // The face of voxel (x, y, z) on `axis`, on its upper side when `upper`.
  void addFace(uint32_t x, uint32_t y, uint32_t z, int axis, bool upper) {
    std::array<uint32_t, 3> base{x, y, z};
    base[axis] += upper;
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    // Corners in the plane: base, +u, +u+v, +v; counter-clockwise seen from +axis.
    std::array<std::array<uint32_t, 3>, 4> corners{base, base, base, base};
    ++corners[1][u];
    ++corners[2][u];
    ++corners[2][v];
    ++corners[3][v];
    uint32_t ids[4];
    for (int i = 0; i < 4; ++i) ids[i] = vertex(corners[i]);
    if (upper) {
      triangle(ids[0], ids[1], ids[2]);
      triangle(ids[0], ids[2], ids[3]);
    } else {  // seen from -axis: the other winding
      triangle(ids[0], ids[2], ids[1]);
      triangle(ids[0], ids[3], ids[2]);
    }
  }
  TriangleMesh take() { return std::move(mesh_); }

 private:
  uint32_t vertex(const std::array<uint32_t, 3>& point) {
    const uint64_t key = (uint64_t{point[2]} * (cells_ + 1) + point[1]) * (cells_ + 1) + point[0];
    const auto [found, added] = ids_.try_emplace(key, static_cast<uint32_t>(mesh_.vertices.size()));
    if (added) mesh_.vertices.push_back(glm::dvec3(point[0], point[1], point[2]) * size_ - 1.0);
    return found->second;
  }
  void triangle(uint32_t a, uint32_t b, uint32_t c) {
    if (mesh_.triangles.size() >= (size_t{1} << 31))
      throw std::runtime_error("voxel faces: more than 2^31 triangles");
    mesh_.triangles.push_back({a, b, c});
  }

  uint32_t cells_;
  double size_;  // a voxel's edge in the root cube
  std::unordered_map<uint64_t, uint32_t> ids_;
  TriangleMesh mesh_;
};

}  // namespace

TriangleMesh voxelFaces(const VoxelSource& source) {
  if (source.depth() > kMaxVoxelFaceDepth)
    throw std::invalid_argument("voxel faces: depth " + std::to_string(source.depth()) +
                                " is beyond the deepest grid they are made for (" +
                                std::to_string(kMaxVoxelFaceDepth) + ")");
  const Occupied occupied(source);
  FaceMesh faces(occupied.cells());
  const uint32_t n = occupied.cells();
  for (uint32_t z = 0; z < n; ++z)
    for (uint32_t y = 0; y < n; ++y)
      for (uint32_t x = 0; x < n; ++x) {
        if (!occupied.solid(x, y, z)) continue;
        const std::array<int64_t, 3> at{x, y, z};
        for (int axis = 0; axis < 3; ++axis)
          for (int side = -1; side <= 1; side += 2) {
            std::array<int64_t, 3> next = at;
            next[axis] += side;
            if (!occupied.solid(next[0], next[1], next[2])) faces.addFace(x, y, z, axis, side > 0);
          }
      }
  return faces.take();
}

}  // namespace rtu
