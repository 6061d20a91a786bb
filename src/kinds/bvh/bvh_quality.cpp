#include "kinds/bvh/bvh_quality.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace rtu {

AccelQuality measureQuality(const BuildTree& tree, const SahCosts& seedCosts) {
  AccelQuality quality;
  quality.triangles = tree.refs.size();
  quality.nodes = tree.nodes.size();
  quality.listEntries = tree.refs.size();
  SahSum sum;
  uint64_t leafTriangles = 0;
  std::vector<std::pair<uint32_t, uint64_t>> pending{{0, 0}};  // node, depth
  while (!pending.empty()) {
    const auto [index, depth] = pending.back();
    pending.pop_back();
    const BuildNode& node = tree.nodes[index];
    quality.depth = std::max(quality.depth, depth);
    if (node.leaf()) {
      ++quality.leaves;
      if (node.count == 0) ++quality.emptyLeaves;
      leafTriangles += node.count;
      quality.trianglesPerLeafMax = std::max<uint64_t>(quality.trianglesPerLeafMax, node.count);
      sum.addLeaf(node.box.area(), node.count);
    } else {
      sum.addInner(node.box.area());
      pending.push_back({node.right, depth + 1});
      pending.push_back({node.left, depth + 1});
    }
  }
  quality.trianglesPerLeafMean =
      static_cast<double>(leafTriangles) / static_cast<double>(quality.leaves);
  const double rootArea = tree.nodes[0].box.area();
  quality.sah = sum.cost(rootArea, SahCosts{});
  quality.sahSeed = sum.cost(rootArea, seedCosts);
  return quality;
}

}  // namespace rtu
