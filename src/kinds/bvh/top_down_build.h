#pragma once
// The frame every top-down BVH builder but the seed's shares (sah_builder.h, lbvh_builder.h):
// the root over all references, then each node in depth-first, left-first order asked of a
// policy how to divide it; children are allocated as an adjacent pair when their parent divides.

#include <cstdint>
#include <utility>
#include <vector>

#include "kinds/bvh/build_primitives.h"
#include "kinds/bvh/build_tree.h"

namespace rtu {

// `divide(refs, node)` reorders refs[node.first, node.first + node.count) so the left child's
// references come first and returns their number: 0 (or node.count) leaves the node a leaf.
template <class Divide>
BuildTree buildTopDown(const BuildPrimitives& primitives, std::vector<uint32_t> refs,
                       Divide&& divide) {
  const auto n = static_cast<uint32_t>(refs.size());
  BuildTree tree;
  tree.refs = std::move(refs);
  tree.nodes.reserve(2 * size_t{n});
  tree.nodes.push_back({primitives.boxOf(tree.refs, 0, n), 0, n});
  std::vector<uint32_t> pending{0};
  while (!pending.empty()) {
    const uint32_t index = pending.back();
    pending.pop_back();
    const BuildNode node = tree.nodes[index];
    const uint32_t leftCount = divide(tree.refs, node);
    if (leftCount == 0 || leftCount >= node.count) continue;
    const uint32_t rightCount = node.count - leftCount;
    const auto left = static_cast<uint32_t>(tree.nodes.size());
    tree.nodes.push_back(
        {primitives.boxOf(tree.refs, node.first, leftCount), node.first, leftCount});
    tree.nodes.push_back({primitives.boxOf(tree.refs, node.first + leftCount, rightCount),
                          node.first + leftCount, rightCount});
    tree.nodes[index].left = left;
    tree.nodes[index].right = left + 1;
    pending.push_back(left + 1);  // the left child first
    pending.push_back(left);
  }
  return tree;
}

}  // namespace rtu
