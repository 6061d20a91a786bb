#include "kinds/bih/bih_quality.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "geometry/aabb.h"

namespace rtu {
namespace {

Aabb<double> boxOf(const GridPoint& lower, const GridPoint& upper) {
  Aabb<double> box;
  for (int k = 0; k < 3; ++k) {
    box.lower[k] = static_cast<double>(lower[k]);
    box.upper[k] = static_cast<double>(upper[k]);
  }
  return box;
}

uint64_t distinctTriangles(const std::vector<uint32_t>& list) {
  std::vector<uint32_t> sorted = list;
  std::sort(sorted.begin(), sorted.end());
  return static_cast<uint64_t>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
}

// A node waiting to be visited, with its clipped box and depth.
struct Visit {
  uint32_t node = 0;
  Aabb<double> box;
  uint64_t depth = 0;
};

}  // namespace

AccelQuality measureQuality(const BihBuild& build, const GridPoint& sceneUpper) {
  AccelQuality quality;
  quality.triangles = distinctTriangles(build.list);
  quality.nodes = build.nodes.size();
  quality.listEntries = build.list.size();
  const Aabb<double> root = boxOf(GridPoint{0, 0, 0}, sceneUpper);
  SahSum sum;
  std::vector<Visit> pending{{0, root, 0}};
  while (!pending.empty()) {
    const Visit visit = pending.back();
    pending.pop_back();
    const BihBuildNode& node = build.nodes[visit.node];
    quality.depth = std::max(quality.depth, visit.depth);
    if (node.leaf) {
      ++quality.leaves;
      if (node.count == 0) ++quality.emptyLeaves;
      quality.trianglesPerLeafMax = std::max<uint64_t>(quality.trianglesPerLeafMax, node.count);
      sum.addLeaf(visit.box.area(), node.count);
      continue;
    }
    sum.addInner(visit.box.area());
    Visit left{node.index, visit.box, visit.depth + 1},
        right{node.index + 1, visit.box, visit.depth + 1};
    left.box.upper[node.axis] = static_cast<double>(node.clip0);
    right.box.lower[node.axis] = static_cast<double>(node.clip1);
    pending.push_back(right);
    pending.push_back(left);
  }
  quality.trianglesPerLeafMean =
      static_cast<double>(quality.listEntries) / static_cast<double>(quality.leaves);
  quality.sah = sum.cost(root.area(), SahCosts{});
  quality.sahSeed = std::numeric_limits<double>::quiet_NaN();
  return quality;
}

}  // namespace rtu
