#include "kinds/bvh/langr_builder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "kinds/bvh/build_primitives.h"

namespace rtu {
namespace {

void checkConfig(const LangrConfig& config) {
  if (config.bins < 2)
    throw std::invalid_argument("langr builder: bins must be at least 2, not " +
                                std::to_string(config.bins));
  if (config.leafThreshold < 1)
    throw std::invalid_argument("langr builder: the leaf threshold must be at least 1");
}

// One bin of Algorithm 4 (L796-806): after the sweeps, `left` holds the bins up to it and
// `right` the bins from it.
struct Bin {
  Aabb<double> leftBox, rightBox;
  uint32_t triangles = 0;
  uint32_t leftTriangles = 0, rightTriangles = 0;
};

// A node's division into two children: the left one's triangle count and both boxes.
struct Split {
  uint32_t leftCount = 0;
  Aabb<double> leftBox, rightBox;
};

class LangrBuilder {
 public:
  // The primitives' AABB centres, in double (L728, B3).
  LangrBuilder(const BuildPrimitives& primitives, const LangrConfig& config)
      : config_(config), primitives_(primitives) {}

  // Algorithm 3 (L745-786).
  LangrBuild build() {
    const auto n = static_cast<uint32_t>(primitives_.boxes.size());
    BuildTree& tree = result_.tree;
    // The seed makes the reference array only when it splits; a root leaf reads it as 0..n-1.
    tree.refs.resize(n);
    std::iota(tree.refs.begin(), tree.refs.end(), 0u);
    const BuildNode root{boxOf(0, n), 0, n};
    tree.nodes.reserve(2 * size_t{n});  // the seed's node pool (L759)
    tree.nodes.push_back(root);         // numBvhNodes = 1 after the root (B5)
    // A root leaf: `<` as printed (L751, B4), or a single primitive, which no split divides (a
    // top level of one instance at threshold 1, two_level.h).
    if (n < config_.leafThreshold || n == 1) return std::move(result_);
    uint32_t current = 0;
    std::vector<uint32_t> pending;  // toSubdivideStack, grown as needed (B5)
    while (true) {
      const uint32_t left = splitNode(current);
      const bool splitLeft = tree.nodes[left].count > config_.leafThreshold;
      const bool splitRight = tree.nodes[left + 1].count > config_.leafThreshold;
      if (splitLeft) {
        if (splitRight) deferNode(pending, left + 1);
        current = left;  // depth first, left first (L774-777)
      } else if (splitRight) {
        current = left + 1;
      } else if (!pending.empty()) {
        current = pending.back();
        pending.pop_back();
      } else {
        break;
      }
    }
    return std::move(result_);
  }

 private:
  void deferNode(std::vector<uint32_t>& pending, uint32_t index) {
    pending.push_back(index);
    result_.maxPendingNodes =
        std::max(result_.maxPendingNodes, static_cast<uint32_t>(pending.size()));
  }

  // Allocates the node's children as the adjacent pair at the end of the pool (L762-763) and
  // divides its triangles between them (L764-773). Returns the left child's index.
  uint32_t splitNode(uint32_t index) {
    std::vector<BuildNode>& nodes = result_.tree.nodes;
    const uint32_t first = nodes[index].first;
    const uint32_t count = nodes[index].count;
    const Split split = divide(first, count);
    const auto left = static_cast<uint32_t>(nodes.size());
    nodes.push_back({split.leftBox, first, split.leftCount});
    nodes.push_back({split.rightBox, first + split.leftCount, count - split.leftCount});
    nodes[index].left = left;
    nodes[index].right = left + 1;
    return left;
  }

  // Algorithm 4, getDividingTri (L788-825), over refs[first, first + count).
  Split divide(uint32_t first, uint32_t count) {
    const std::vector<uint32_t>& refs = result_.tree.refs;
    Aabb<double> centres;
    for (uint32_t i = first; i < first + count; ++i) centres.grow(primitives_.centres[refs[i]]);
    const int axis = widestAxis(centres);  // the first of equal extents (B6)
    const double lower = centres.lower[axis];
    const double extent = centres.upper[axis] - lower;
    if (extent == 0) return medianSplit(first, count);  // all centres coincide (B2)
    std::vector<Bin> bins(config_.bins);                // reset at every call (B5)
    std::vector<uint32_t> binOf(count);                 // the seed's triangle.binIndex (L796)
    for (uint32_t i = 0; i < count; ++i) {
      const uint32_t triangle = refs[first + i];
      binOf[i] = binIndex(primitives_.centres[triangle][axis], lower, extent);
      Bin& bin = bins[binOf[i]];
      bin.leftBox.merge(
          primitives_.boxes[triangle]);  // the bins bound triangles, not centres (L797-798)
      bin.rightBox.merge(primitives_.boxes[triangle]);
      ++bin.triangles;
    }
    sweep(bins);
    const uint32_t divider = cheapestDivider(bins);
    return {partition(first, binOf, divider), bins[divider].leftBox, bins[divider + 1].rightBox};
  }

  // numBins * (c - min) / (max - min) in double, in that order, truncated (L794-795, B3); the
  // greatest centre gives numBins, and rounding may too: clamped to the last bin (B1).
  uint32_t binIndex(double centre, double lower, double extent) const {
    const double scaled = static_cast<double>(config_.bins) * (centre - lower) / extent;
    return std::min(static_cast<uint32_t>(scaled), config_.bins - 1);
  }

  // The prefix and suffix sweeps (L800-805).
  static void sweep(std::vector<Bin>& bins) {
    bins.front().leftTriangles = bins.front().triangles;
    for (size_t i = 1; i < bins.size(); ++i) {
      bins[i].leftBox.merge(bins[i - 1].leftBox);
      bins[i].leftTriangles = bins[i].triangles + bins[i - 1].leftTriangles;
    }
    bins.back().rightTriangles = bins.back().triangles;
    for (size_t i = bins.size() - 1; i-- > 0;) {
      bins[i].rightBox.merge(bins[i + 1].rightBox);
      bins[i].rightTriangles = bins[i].triangles + bins[i + 1].rightTriangles;
    }
  }

  // The last bin of the left child: the least SAH, the first of equal ones (strict `<`,
  // L806-812). No costs and no parent area: they would not change the choice.
  static uint32_t cheapestDivider(const std::vector<Bin>& bins) {
    double best = std::numeric_limits<double>::infinity();
    uint32_t divider = 0;
    for (uint32_t i = 0; i + 1 < bins.size(); ++i) {
      const double sah = bins[i].leftBox.area() * bins[i].leftTriangles +
                         bins[i + 1].rightBox.area() * bins[i + 1].rightTriangles;
      if (sah < best) {
        best = sah;
        divider = i;
      }
    }
    return divider;
  }

  // One pass over a copy (L814-824): bins up to `divider` are written from the front in order,
  // the others from the back, so the right part comes out reversed. The copy is indexed from
  // `first` (B5). Returns the left count.
  uint32_t partition(uint32_t first, const std::vector<uint32_t>& binOf, uint32_t divider) {
    std::vector<uint32_t>& refs = result_.tree.refs;
    const auto count = static_cast<uint32_t>(binOf.size());
    const std::vector<uint32_t> copy(refs.begin() + first, refs.begin() + first + count);
    uint32_t left = first;
    uint32_t right = first + count - 1;
    for (uint32_t i = 0; i < count; ++i) {
      if (binOf[i] > divider)
        refs[right--] = copy[i];
      else
        refs[left++] = copy[i];
    }
    return left - first;
  }

  // B2: the references split in half in their current order, counted.
  Split medianSplit(uint32_t first, uint32_t count) {
    ++result_.forcedMedians;
    const uint32_t half = count / 2;
    return {half, boxOf(first, half), boxOf(first + half, count - half)};
  }

  Aabb<double> boxOf(uint32_t first, uint32_t count) const {
    return primitives_.boxOf(result_.tree.refs, first, count);
  }

  const LangrConfig& config_;
  const BuildPrimitives& primitives_;
  LangrBuild result_;
};

}  // namespace

LangrBuild buildLangr(const BuildPrimitives& primitives, const LangrConfig& config) {
  checkConfig(config);
  checkPrimitives(primitives, "langr");
  return LangrBuilder(primitives, config).build();
}

LangrBuild buildLangr(const TriangleMesh& mesh, const LangrConfig& config) {
  return buildLangr(buildPrimitives(mesh, "langr"), config);
}

}  // namespace rtu
