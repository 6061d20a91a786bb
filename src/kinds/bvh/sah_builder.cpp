#include "kinds/bvh/sah_builder.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "kinds/bvh/build_primitives.h"
#include "kinds/bvh/top_down_build.h"

namespace rtu {
namespace {

std::string builderName(const SahBuilderConfig& config) {
  return config.search == SahSplitSearch::Binned ? "binned" : "sweep";
}

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
  SahBuilder(const BuildPrimitives& primitives, const SahBuilderConfig& config)
      : config_(config), primitives_(primitives) {}

  SahBuild build() {
    std::vector<uint32_t> refs(primitives_.boxes.size());
    std::iota(refs.begin(), refs.end(), 0u);
    SahBuild result;
    result.tree = buildTopDown(primitives_, std::move(refs),
                               [&](std::vector<uint32_t>& refs, const BuildNode& node) {
                                 return divide(refs, node, result.forcedMedians);
                               });
    return result;
  }

 private:
  // The left child's count after reordering the node's references, or 0 to leave it a leaf.
  uint32_t divide(std::vector<uint32_t>& refs, const BuildNode& node, uint32_t& forcedMedians) {
    if (node.count == 1) return 0;
    const Split split = bestSplit(refs, node);
    const double leafCost = config_.costs.triangle * node.count;
    if (node.count <= config_.maxLeafSize && leafCost <= split.cost) return 0;
    if (split.axis >= 0) return partition(refs, node, split);
    ++forcedMedians;  // no split found: all centres coincide
    return node.count / 2;
  }

  Split bestSplit(const std::vector<uint32_t>& refs, const BuildNode& node) {
    Split best;
    const Aabb<double> centres = centresOf(refs, node);
    for (int axis = 0; axis < 3; ++axis) {
      ranks(refs, node, centres, axis, ranks_);
      considerSplits(refs, node, axis, best);
    }
    return best;
  }

  Aabb<double> centresOf(const std::vector<uint32_t>& refs, const BuildNode& node) const {
    Aabb<double> centres;
    for (uint32_t i = 0; i < node.count; ++i)
      centres.grow(primitives_.centres[refs[node.first + i]]);
    return centres;
  }

  // Embree's number of bins for a node of `count` references: min(bins, 4 + count / 20), so small
  // nodes sweep few bins.
  uint32_t binsFor(uint32_t count) const { return std::min(config_.bins, 4 + count / 20); }

  // Each reference's rank on `axis`: its bin, or its position in centre order (ties by triangle
  // index); references of equal rank never go to different sides.
  void ranks(const std::vector<uint32_t>& refs, const BuildNode& node, const Aabb<double>& centres,
             int axis, std::vector<uint32_t>& out) {
    out.resize(node.count);
    if (config_.search == SahSplitSearch::Binned) {
      const uint32_t bins = binsFor(node.count);
      const double lower = centres.lower[axis], extent = centres.upper[axis] - lower;
      // Bins per unit of the centres' extent: infinite for an extent below about 1e-307, so an
      // offset of 0 is bin 0 by itself and anything at or past `bins` the last bin.
      const double scale = extent > 0 ? bins / extent : 0;
      for (uint32_t i = 0; i < node.count; ++i) {
        const double offset = primitives_.centres[refs[node.first + i]][axis] - lower;
        const double scaled = offset > 0 ? offset * scale : 0.0;
        out[i] = scaled < bins ? static_cast<uint32_t>(scaled) : bins - 1;
      }
      return;
    }
    std::vector<uint32_t>& order = order_;
    order.resize(node.count);
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
  void considerSplits(const std::vector<uint32_t>& refs, const BuildNode& node, int axis,
                      Split& best) {
    const uint32_t slots = config_.search == SahSplitSearch::Binned ? binsFor(node.count)
                                                                    : node.count;
    std::vector<Aabb<double>>& boxes = slotBoxes_;
    std::vector<uint32_t>& counts = slotCounts_;
    boxes.assign(slots, Aabb<double>{});
    counts.assign(slots, 0);
    for (uint32_t i = 0; i < node.count; ++i) {
      boxes[ranks_[i]].merge(primitives_.boxes[refs[node.first + i]]);
      ++counts[ranks_[i]];
    }
    // Right sides from the back: the box and count of slots >= s.
    std::vector<Aabb<double>>& rightBox = rightBoxes_;
    std::vector<uint32_t>& rightCount = rightCounts_;
    rightBox.assign(slots + 1, Aabb<double>{});
    rightCount.assign(slots + 1, 0);
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
  uint32_t partition(std::vector<uint32_t>& refs, const BuildNode& node, const Split& split) {
    ranks(refs, node, centresOf(refs, node), split.axis, ranks_);
    const auto begin = refs.begin() + node.first;
    order_.assign(begin, begin + node.count);  // a copy, read while refs are rewritten
    uint32_t left = 0;
    for (uint32_t i = 0; i < node.count; ++i)
      if (ranks_[i] < split.rankLimit) begin[left++] = order_[i];
    uint32_t right = left;
    for (uint32_t i = 0; i < node.count; ++i)
      if (ranks_[i] >= split.rankLimit) begin[right++] = order_[i];
    return left;
  }

  const SahBuilderConfig& config_;
  const BuildPrimitives& primitives_;
  // Scratch, kept between nodes so that no node allocates: the references' ranks on one axis,
  // an order or copy of them, and each slot's box and count and those of the slots from it on.
  std::vector<uint32_t> ranks_, order_;
  std::vector<Aabb<double>> slotBoxes_, rightBoxes_;
  std::vector<uint32_t> slotCounts_, rightCounts_;
};

}  // namespace

SahBuild buildSah(const BuildPrimitives& primitives, const SahBuilderConfig& config) {
  checkConfig(config);
  checkPrimitives(primitives, builderName(config));
  return SahBuilder(primitives, config).build();
}

SahBuild buildSah(const TriangleMesh& mesh, const SahBuilderConfig& config) {
  return buildSah(buildPrimitives(mesh, builderName(config)), config);
}

}  // namespace rtu
