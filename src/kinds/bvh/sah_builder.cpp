#include "kinds/bvh/sah_builder.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "kinds/bvh/build_primitives.h"

namespace rtu {
namespace {

void checkConfig(const SahBuilderConfig& config) {
  if (config.search == SahSplitSearch::Binned && config.bins < 2)
    throw std::invalid_argument("binned builder: bins must be at least 2, not " +
                                std::to_string(config.bins));
  if (config.maxLeafSize < 1)
    throw std::invalid_argument("SAH builder: the maximum leaf size must be at least 1");
}

// A node's best division: the references whose rank on `axis` (a bin index, or a position in
// centre order) is below `rankLimit` go left.
struct Split {
  int axis = -1;  // -1: none found
  uint32_t rankLimit = 0;
  double cost = std::numeric_limits<double>::infinity();
};

class SahBuilder {
 public:
  SahBuilder(const TriangleMesh& mesh, const SahBuilderConfig& config)
      : config_(config), primitives_(buildPrimitives(mesh, builderName(config))) {}

  SahBuild build() {
    const auto n = static_cast<uint32_t>(primitives_.boxes.size());
    BuildTree& tree = result_.tree;
    tree.refs.resize(n);
    std::iota(tree.refs.begin(), tree.refs.end(), 0u);
    tree.nodes.reserve(2 * size_t{n});
    tree.nodes.push_back({primitives_.boxOf(tree.refs, 0, n), 0, n});
    std::vector<uint32_t> pending{0};
    while (!pending.empty()) {
      const uint32_t node = pending.back();
      pending.pop_back();
      if (!subdivide(node)) continue;
      pending.push_back(tree.nodes[node].right);  // the left child first
      pending.push_back(tree.nodes[node].left);
    }
    return std::move(result_);
  }

 private:
  static std::string builderName(const SahBuilderConfig& config) {
    return config.search == SahSplitSearch::Binned ? "binned" : "sweep";
  }

  // Splits the node into two children, or leaves it a leaf; whether it split.
  bool subdivide(uint32_t index) {
    const BuildNode node = result_.tree.nodes[index];
    if (node.count == 1) return false;
    Split split = bestSplit(node);
    const double leafCost = config_.costs.triangle * node.count;
    if (node.count <= config_.maxLeafSize && leafCost <= split.cost) return false;
    uint32_t leftCount = node.count / 2;  // no split found: all centres coincide
    if (split.axis < 0)
      ++result_.forcedMedians;
    else
      leftCount = partition(node, split);
    addChildren(index, leftCount);
    return true;
  }

  void addChildren(uint32_t index, uint32_t leftCount) {
    BuildTree& tree = result_.tree;
    const uint32_t first = tree.nodes[index].first, count = tree.nodes[index].count;
    const auto left = static_cast<uint32_t>(tree.nodes.size());
    tree.nodes.push_back({primitives_.boxOf(tree.refs, first, leftCount), first, leftCount});
    tree.nodes.push_back({primitives_.boxOf(tree.refs, first + leftCount, count - leftCount),
                          first + leftCount, count - leftCount});
    tree.nodes[index].left = left;
    tree.nodes[index].right = left + 1;
  }

  Split bestSplit(const BuildNode& node) {
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
      ranks(node, axis, ranks_);
      considerSplits(node, axis, best);
    }
    return best;
  }

  // Each reference's rank on `axis`: its bin, or its position in centre order (ties by triangle
  // index); references of equal rank never go to different sides.
  void ranks(const BuildNode& node, int axis, std::vector<uint32_t>& out) const {
    const std::vector<uint32_t>& refs = result_.tree.refs;
    out.resize(node.count);
    if (config_.search == SahSplitSearch::Binned) {
      Aabb<double> centres;
      for (uint32_t i = 0; i < node.count; ++i)
        centres.grow(primitives_.centres[refs[node.first + i]]);
      const double lower = centres.lower[axis], extent = centres.upper[axis] - lower;
      for (uint32_t i = 0; i < node.count; ++i) {
        const double scaled =
            extent > 0
                ? config_.bins * (primitives_.centres[refs[node.first + i]][axis] - lower) / extent
                : 0;
        out[i] = std::min(static_cast<uint32_t>(scaled), config_.bins - 1);
      }
      return;
    }
    std::vector<uint32_t> order(node.count);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
      const uint32_t ta = refs[node.first + a], tb = refs[node.first + b];
      const double ca = primitives_.centres[ta][axis], cb = primitives_.centres[tb][axis];
      return ca < cb || (ca == cb && ta < tb);
    });
    // Equal centres share the rank of the first of them, so no split separates them.
    for (uint32_t position = 0; position < node.count; ++position) {
      const bool tie =
          position > 0 && primitives_.centres[refs[node.first + order[position]]][axis] ==
                              primitives_.centres[refs[node.first + order[position - 1]]][axis];
      out[order[position]] = tie ? out[order[position - 1]] : position;
    }
  }

  // Sweeps the ranks on `axis` and keeps any split cheaper than `best`.
  void considerSplits(const BuildNode& node, int axis, Split& best) {
    const uint32_t slots = config_.search == SahSplitSearch::Binned ? config_.bins : node.count;
    std::vector<Aabb<double>> boxes(slots);
    std::vector<uint32_t> counts(slots, 0);
    for (uint32_t i = 0; i < node.count; ++i) {
      boxes[ranks_[i]].merge(primitives_.boxes[result_.tree.refs[node.first + i]]);
      ++counts[ranks_[i]];
    }
    // Right sides from the back: the box and count of slots >= s.
    std::vector<Aabb<double>> rightBox(slots + 1);
    std::vector<uint32_t> rightCount(slots + 1, 0);
    for (uint32_t s = slots; s-- > 0;) {
      rightBox[s] = rightBox[s + 1];
      rightBox[s].merge(boxes[s]);
      rightCount[s] = rightCount[s + 1] + counts[s];
    }
    const double nodeArea = node.box.area();
    Aabb<double> leftBox;
    uint32_t leftCount = 0;
    for (uint32_t s = 1; s < slots; ++s) {
      leftBox.merge(boxes[s - 1]);
      leftCount += counts[s - 1];
      if (leftCount == 0 || rightCount[s] == 0) continue;
      const double cost = config_.costs.box +
                          config_.costs.triangle *
                              (leftBox.area() * leftCount + rightBox[s].area() * rightCount[s]) /
                              nodeArea;
      if (cost < best.cost) best = Split{axis, s, cost};
    }
  }

  // Moves the references of rank below the split's limit on its axis to the front, keeping the
  // order on either side. Returns the left count.
  uint32_t partition(const BuildNode& node, const Split& split) {
    ranks(node, split.axis, ranks_);
    std::vector<uint32_t>& refs = result_.tree.refs;
    std::vector<uint32_t> left, right;
    for (uint32_t i = 0; i < node.count; ++i)
      (ranks_[i] < split.rankLimit ? left : right).push_back(refs[node.first + i]);
    std::copy(left.begin(), left.end(), refs.begin() + node.first);
    std::copy(right.begin(), right.end(), refs.begin() + node.first + left.size());
    return static_cast<uint32_t>(left.size());
  }

  const SahBuilderConfig& config_;
  BuildPrimitives primitives_;
  std::vector<uint32_t> ranks_;  // scratch: the current node's references' ranks on one axis
  SahBuild result_;
};

}  // namespace

SahBuild buildSah(const TriangleMesh& mesh, const SahBuilderConfig& config) {
  checkConfig(config);
  return SahBuilder(mesh, config).build();
}

}  // namespace rtu
