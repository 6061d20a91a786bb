#include "kinds/svo/svo_size_estimate.h"

#include <vector>

namespace rtu {
namespace {

// Levels with more mixed nodes than this are extrapolated rather than counted.
constexpr size_t kCountedNodes = size_t{1} << 14;

std::vector<OctreeNode> mixedNodes(const VoxelSource& source,
                                   const std::vector<OctreeNode>& nodes) {
  std::vector<OctreeNode> mixed;
  for (const OctreeNode& node : nodes)
    if (source.classify(node) == Occupancy::Mixed) mixed.push_back(node);
  return mixed;
}

std::vector<OctreeNode> childrenOf(const std::vector<OctreeNode>& nodes) {
  std::vector<OctreeNode> children;
  children.reserve(nodes.size() * 8);
  for (const OctreeNode& node : nodes)
    for (int slot = 0; slot < 8; ++slot) children.push_back(node.child(slot));
  return children;
}

double estimateDescriptors(const VoxelSource& source) {
  std::vector<OctreeNode> level{OctreeNode{}};
  double total = 0;
  double previous = 0;
  for (int depth = 0; depth < source.depth(); ++depth) {
    const std::vector<OctreeNode> mixed = mixedNodes(source, level);
    const auto count = static_cast<double>(mixed.size());
    total += count;
    if (mixed.empty()) break;
    if (mixed.size() > kCountedNodes) {
      const double growth = previous > 0 ? count / previous : 8.0;
      double below = count;
      for (int rest = depth + 1; rest < source.depth(); ++rest) total += below *= growth;
      break;
    }
    previous = count;
    level = childrenOf(mixed);
  }
  return total;
}

}  // namespace

SvoSizeEstimate estimateSvoSize(const VoxelSource& source, uint32_t rootAddress) {
  SvoSizeEstimate estimate;
  estimate.descriptors = estimateDescriptors(source);
  estimate.imageBytes = 4.0 * (estimate.descriptors + rootAddress);
  // The blocks of a subtree and the block they are copied into coexist, and so do the finished
  // tree and the image it is copied into.
  estimate.peakBytes = 2.0 * estimate.imageBytes;
  return estimate;
}

}  // namespace rtu
