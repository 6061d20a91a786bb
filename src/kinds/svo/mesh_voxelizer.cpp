#include "kinds/svo/mesh_voxelizer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "kinds/svo/svo_builder.h"

namespace rtu {
namespace {

const std::array<glm::dvec3, 3> kBoxAxes = {glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0),
                                            glm::dvec3(0, 0, 1)};

struct Box {
  glm::dvec3 lower, upper;

  glm::dvec3 centre() const { return 0.5 * (lower + upper); }
};

Box boundsOf(const std::array<glm::dvec3, 3>& triangle) {
  return {glm::min(glm::min(triangle[0], triangle[1]), triangle[2]),
          glm::max(glm::max(triangle[0], triangle[1]), triangle[2])};
}

// The separating-axis tests along the box's own axes.
bool boxesOverlap(const Box& a, const Box& b) {
  return glm::all(glm::lessThanEqual(a.lower, b.upper)) &&
         glm::all(glm::lessThanEqual(b.lower, a.upper));
}

bool isAncestorOrSelf(const OctreeNode& ancestor, const OctreeNode& node) {
  if (ancestor.level < 0 || ancestor.level > node.level) return false;
  const int shift = node.level - ancestor.level;
  return node.x >> shift == ancestor.x && node.y >> shift == ancestor.y &&
         node.z >> shift == ancestor.z;
}

void requireFinite(const glm::dvec3& v, uint32_t index) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
    throw std::invalid_argument("mesh vertex " + std::to_string(index) +
                                " has a non-finite coordinate");
}

// Bounding box of the vertices that triangles use (stray vertices do not widen the fit).
Box triangleBounds(const TriangleMesh& mesh) {
  Box bounds{glm::dvec3(std::numeric_limits<double>::max()),
             glm::dvec3(std::numeric_limits<double>::lowest())};
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (uint32_t index : mesh.triangles[t]) {
      if (index >= mesh.vertices.size())
        throw std::invalid_argument("mesh triangle " + std::to_string(t) + " uses vertex " +
                                    std::to_string(index) + " of " +
                                    std::to_string(mesh.vertices.size()));
      const glm::dvec3& v = mesh.vertices[index];
      requireFinite(v, index);
      bounds.lower = glm::min(bounds.lower, v);
      bounds.upper = glm::max(bounds.upper, v);
    }
  }
  return bounds;
}

// Whether the projections p0, p1 of a triangle onto an axis miss the box's projection [-r, r].
bool separated(double p0, double p1, double r) {
  return std::min(p0, p1) > r || std::max(p0, p1) < -r;
}

// The remaining separating-axis tests: the triangle's normal and the nine cross products of its
// edges with the box axes. A zero axis (from a degenerate triangle) never separates, so a
// degenerate triangle is tested as the segment or point it is.
bool planeAndEdgeAxesOverlap(const std::array<glm::dvec3, 3>& triangle, const glm::dvec3& boxCentre,
                             const glm::dvec3& boxHalfSize) {
  const std::array<glm::dvec3, 3> v = {triangle[0] - boxCentre, triangle[1] - boxCentre,
                                       triangle[2] - boxCentre};
  const std::array<glm::dvec3, 3> edges = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
  const glm::dvec3 normal = glm::cross(edges[0], edges[1]);
  const double planeDistance = glm::dot(normal, v[0]);  // every vertex projects here
  if (separated(planeDistance, planeDistance, glm::dot(boxHalfSize, glm::abs(normal))))
    return false;
  for (int k = 0; k < 3; ++k) {
    // Both ends of edge k project alike onto an axis across it: test one and the opposite vertex.
    const glm::dvec3& end = v[k];
    const glm::dvec3& opposite = v[(k + 2) % 3];
    for (const glm::dvec3& boxAxis : kBoxAxes) {
      const glm::dvec3 axis = glm::cross(edges[k], boxAxis);
      if (separated(glm::dot(end, axis), glm::dot(opposite, axis),
                    glm::dot(boxHalfSize, glm::abs(axis))))
        return false;
    }
  }
  return true;
}

}  // namespace

bool triangleOverlapsBox(const std::array<glm::dvec3, 3>& triangle, const glm::dvec3& boxCentre,
                         const glm::dvec3& boxHalfSize) {
  if (!boxesOverlap(boundsOf(triangle), Box{boxCentre - boxHalfSize, boxCentre + boxHalfSize}))
    return false;
  return planeAndEdgeAxesOverlap(triangle, boxCentre, boxHalfSize);
}

MeshVoxelizer::MeshVoxelizer(const TriangleMesh& mesh, int depth) : depth_(depth) {
  if (depth < 2 || depth > kMaxSvoDepth)
    throw std::invalid_argument("mesh voxelization depth must be 2 to " +
                                std::to_string(kMaxSvoDepth) + ", got " + std::to_string(depth));
  if (mesh.triangles.empty()) throw std::invalid_argument("mesh to voxelize has no triangles");

  const Box bounds = triangleBounds(mesh);
  const glm::dvec3 extent = bounds.upper - bounds.lower;
  const double longest = std::max({extent.x, extent.y, extent.z});
  if (!(longest > 0.0))
    throw std::invalid_argument("mesh to voxelize has all its triangle vertices at one point");
  const double voxel = 2.0 / static_cast<double>(1u << depth);
  scale_ = (2.0 - 2.0 * voxel) / longest;
  offset_ = -bounds.centre() * scale_;

  triangles_.reserve(mesh.triangles.size());
  for (const std::array<uint32_t, 3>& indices : mesh.triangles) {
    FittedTriangle triangle;
    for (int i = 0; i < 3; ++i) triangle.vertices[i] = mesh.vertices[indices[i]] * scale_ + offset_;
    const Box triangleBox = boundsOf(triangle.vertices);
    triangle.lower = triangleBox.lower;
    triangle.upper = triangleBox.upper;
    triangles_.push_back(triangle);
  }
  allTriangles_.resize(triangles_.size());
  std::iota(allTriangles_.begin(), allTriangles_.end(), 0u);
  cache_.resize(static_cast<size_t>(depth_));
}

bool MeshVoxelizer::overlaps(uint32_t triangleIndex, const glm::dvec3& lower,
                             const glm::dvec3& upper) const {
  const FittedTriangle& triangle = triangles_[triangleIndex];
  if (!boxesOverlap(Box{triangle.lower, triangle.upper}, Box{lower, upper})) return false;
  return planeAndEdgeAxesOverlap(triangle.vertices, 0.5 * (lower + upper), 0.5 * (upper - lower));
}

// The parent's triangles, classified first when the parent is not the one cached at its level:
// the builder classifies depth first, so that is rare; the size estimate's level-by-level walk
// takes a node's eight children in turn, so the parent is found once for them (and not, as
// when falling back to every triangle, 16,384 nodes a level times every triangle of the mesh).
const std::vector<uint32_t>& MeshVoxelizer::candidatesFor(const OctreeNode& node) const {
  return node.level == 0 ? allTriangles_ : overlappingTriangles(node.parent());
}

const std::vector<uint32_t>& MeshVoxelizer::overlappingTriangles(const OctreeNode& node) const {
  LevelCache& entry = cache_[node.level];
  if (entry.node.level == node.level && isAncestorOrSelf(entry.node, node))
    return entry.triangles;                                       // asked again about the same node
  const std::vector<uint32_t>& candidates = candidatesFor(node);  // from levels above: no alias
  const glm::dvec3 lower = node.lower();
  const glm::dvec3 upper = node.upper();
  entry.node = node;
  entry.triangles.clear();
  for (uint32_t t : candidates)
    if (overlaps(t, lower, upper)) entry.triangles.push_back(t);
  return entry.triangles;
}

Occupancy MeshVoxelizer::classify(const OctreeNode& node) const {
  if (node.level < 0 || node.level > depth_)
    throw std::invalid_argument("node level " + std::to_string(node.level) +
                                " is outside the voxelization's levels 0 to " +
                                std::to_string(depth_));
  if (node.level < depth_)
    return overlappingTriangles(node).empty() ? Occupancy::Empty : Occupancy::Mixed;

  // Voxels have no children to serve, so they stop at the first overlap and are not cached.
  const std::vector<uint32_t>& candidates = candidatesFor(node);
  const glm::dvec3 lower = node.lower();
  const glm::dvec3 upper = node.upper();
  const bool solid = std::any_of(candidates.begin(), candidates.end(),
                                 [&](uint32_t t) { return overlaps(t, lower, upper); });
  return solid ? Occupancy::Full : Occupancy::Empty;
}

}  // namespace rtu
