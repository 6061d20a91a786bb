#include "kinds/bih/bih_builder.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace rtu {
namespace {

// A candidate box on the half grid: every bound a sum lower + upper of grid bounds.
struct Candidate {
  GridPoint lower{}, upper{};

  int longestAxis() const {
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (extent(k) > extent(axis)) axis = k;  // ties: the smallest index
    return axis;
  }
  int64_t extent(int k) const { return upper[k] - lower[k]; }
};

int64_t centreSum(const GridBox& box, int axis) { return box.lower[axis] + box.upper[axis]; }

class Builder {
 public:
  Builder(const std::vector<GridBox>& boxes, const BihBuildSettings& settings)
      : boxes_(boxes), settings_(settings), items_(boxes.size()) {
    for (uint32_t i = 0; i < items_.size(); ++i) items_[i] = i;
  }

  BihBuild run(const GridPoint& sceneUpper) {
    Candidate root;
    for (int k = 0; k < 3; ++k) root.upper[k] = 2 * sceneUpper[k];
    out_.nodes.resize(1);
    build(0, 0, static_cast<uint32_t>(items_.size()), root, 0);
    return std::move(out_);
  }

 private:
  // Makes node `node` of items_[begin, end), splitting `candidate` until both sides hold items.
  void build(uint32_t node, uint32_t begin, uint32_t end, Candidate candidate, uint32_t depth) {
    out_.depth = std::max(out_.depth, depth);
    while (end - begin > settings_.leafSize && depth < kBihMaxDepth) {
      const int axis = candidate.longestAxis();
      if (candidate.extent(axis) < 2) break;  // under one grid unit: the centres cannot part
      const int64_t middle = (candidate.lower[axis] + candidate.upper[axis]) / 2;  // both >= 0
      const auto left = [&](uint32_t item) { return centreSum(boxes_[item], axis) <= middle; };
      const auto split = std::stable_partition(items_.begin() + begin, items_.begin() + end, left);
      const auto mid = static_cast<uint32_t>(split - items_.begin());
      Candidate leftHalf = candidate, rightHalf = candidate;
      leftHalf.upper[axis] = middle;
      rightHalf.lower[axis] = middle + 1;
      if (mid == begin || mid == end) {  // one side empty: shrink, emit nothing
        candidate = mid == begin ? rightHalf : leftHalf;
        continue;
      }
      const auto child = static_cast<uint32_t>(out_.nodes.size());
      out_.nodes.resize(child + 2);
      out_.nodes[node] = inner(axis, begin, mid, end, child);
      build(child, begin, mid, leftHalf, depth + 1);
      build(child + 1, mid, end, rightHalf, depth + 1);
      return;
    }
    makeLeaf(node, begin, end);
  }

  BihBuildNode inner(int axis, uint32_t begin, uint32_t mid, uint32_t end, uint32_t child) const {
    BihBuildNode node;
    node.axis = static_cast<uint32_t>(axis);
    node.index = child;
    node.clip0 = boxUpper(begin, axis);
    for (uint32_t i = begin; i < mid; ++i) node.clip0 = std::max(node.clip0, boxUpper(i, axis));
    node.clip1 = boxLower(mid, axis);
    for (uint32_t i = mid; i < end; ++i) node.clip1 = std::min(node.clip1, boxLower(i, axis));
    return node;
  }
  // The bounds of the triangle at position `i` of items_.
  int64_t boxUpper(uint32_t i, int axis) const { return boxes_[items_[i]].upper[axis]; }
  int64_t boxLower(uint32_t i, int axis) const { return boxes_[items_[i]].lower[axis]; }

  void makeLeaf(uint32_t node, uint32_t begin, uint32_t end) {
    BihBuildNode& leaf = out_.nodes[node];
    leaf.leaf = true;
    leaf.index = static_cast<uint32_t>(out_.list.size());
    leaf.count = end - begin;
    out_.list.insert(out_.list.end(), items_.begin() + begin, items_.begin() + end);
  }

  const std::vector<GridBox>& boxes_;
  const BihBuildSettings settings_;
  std::vector<uint32_t> items_;  // triangle numbers, partitioned in place as the tree grows
  BihBuild out_;
};

}  // namespace

BihBuild buildBih(const std::vector<GridBox>& boxes, const GridPoint& sceneUpper,
                  const BihBuildSettings& settings) {
  if (boxes.empty()) throw std::invalid_argument("BIH build: there are no triangles");
  if (settings.leafSize == 0) throw std::invalid_argument("BIH build: the leaf size must be >= 1");
  return Builder(boxes, settings).run(sceneUpper);
}

std::vector<GridBox> triangleBoxes(const TriangleMesh& mesh, const SceneGrid& grid,
                                   const ProjectedMesh& projected) {
  std::vector<GridBox> boxes;
  boxes.reserve(projected.triangles.size());
  for (const ProjectedTriangle& triangle : projected.triangles) {
    GridBox box;
    for (int corner = 0; corner < 3; ++corner) {
      const GridPoint p = grid.quantise(mesh.vertices[mesh.triangles[triangle.source][corner]]);
      for (int k = 0; k < 3; ++k) {
        box.lower[k] = corner == 0 ? p[k] : std::min(box.lower[k], p[k]);
        box.upper[k] = corner == 0 ? p[k] : std::max(box.upper[k], p[k]);
      }
    }
    boxes.push_back(box);
  }
  return boxes;
}

GridPoint sceneUpper(const SceneGrid& grid) { return grid.quantise(grid.box().upper); }

}  // namespace rtu
