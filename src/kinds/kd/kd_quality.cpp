#include "kinds/kd/kd_quality.h"

#include <algorithm>
#include <unordered_set>
#include <vector>

namespace rtu {
namespace {

struct Cell {
  uint32_t node = 0;
  Aabb<double> box;
  uint64_t depth = 0;
};

// The two children's cells of an inner node's cell.
std::pair<Aabb<double>, Aabb<double>> splitCell(const Aabb<double>& box, const KdBuildNode& node) {
  Aabb<double> below = box, above = box;
  below.upper[node.axis] = node.split;
  above.lower[node.axis] = node.split;
  return {below, above};
}

}  // namespace

AccelQuality measureQuality(const KdBuild& build, const PbrtKdParameters& parameters) {
  AccelQuality quality;
  quality.nodes = build.nodes.size();
  quality.listEntries = build.lists.size();
  quality.triangles = std::unordered_set<uint32_t>(build.lists.begin(), build.lists.end()).size();
  const Aabb<double> root{glm::dvec3(build.bounds.lower), glm::dvec3(build.bounds.upper)};
  SahSum sum;
  std::vector<Cell> pending{{0, root, 0}};
  while (!pending.empty()) {
    const Cell cell = pending.back();
    pending.pop_back();
    const KdBuildNode& node = build.nodes[cell.node];
    quality.depth = std::max(quality.depth, cell.depth);
    if (node.leaf) {
      ++quality.leaves;
      quality.emptyLeaves += node.count == 0;
      quality.trianglesPerLeafMax = std::max<uint64_t>(quality.trianglesPerLeafMax, node.count);
      sum.addLeaf(cell.box.area(), node.count);
      continue;
    }
    sum.addInner(cell.box.area());
    const auto [below, above] = splitCell(cell.box, node);
    pending.push_back({node.above, above, cell.depth + 1});
    pending.push_back({cell.node + 1, below, cell.depth + 1});
  }
  quality.trianglesPerLeafMean =
      quality.leaves ? static_cast<double>(quality.listEntries) / quality.leaves : 0.0;
  quality.sah = sum.cost(root.area(), SahCosts{1.0, 1.0});
  quality.sahSeed =
      sum.cost(root.area(), SahCosts{static_cast<double>(parameters.traversalCost),
                                     static_cast<double>(parameters.intersectionCost)});
  return quality;
}

}  // namespace rtu
