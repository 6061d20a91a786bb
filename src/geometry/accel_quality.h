#pragma once
// The quality figures of any triangle acceleration structure (BVH and BIH now; k-d tree later),
// with the JSON keys, and the surface area heuristic summed over a tree's nodes.

#include <cstdint>

#include <nlohmann/json_fwd.hpp>

namespace rtu {

// The cost of one box test and one triangle test.
struct SahCosts {
  double box = 1.0;
  double triangle = 1.0;
};

// The SAH of a tree, summed node by node: (1/A_root)(C_box Σ_inner A + C_tri Σ_leaf A·n), where
// A is a node's box area and n its triangles. The root counts as an inner node unless it is the
// only leaf.
class SahSum {
 public:
  void addInner(double area) { innerArea_ += area; }
  void addLeaf(double area, uint64_t triangles) {
    leafTriangleArea_ += area * static_cast<double>(triangles);
  }
  // NaN when the root box has no area (all triangles on one line or point).
  double cost(double rootArea, const SahCosts& costs) const {
    return (costs.box * innerArea_ + costs.triangle * leafTriangleArea_) / rootArea;
  }

 private:
  double innerArea_ = 0;
  double leafTriangleArea_ = 0;
};

struct AccelQuality {
  uint64_t triangles = 0;
  uint64_t nodes = 0;
  uint64_t leaves = 0;
  uint64_t emptyLeaves = 0;
  uint64_t depth = 0;  // edges from the root to the deepest leaf
  // Entries of the leaves' triangle lists: the references (each triangle once) of a BVH, the list
  // words of a BIH or k-d tree, where a triangle may be listed in several leaves.
  uint64_t listEntries = 0;
  double trianglesPerLeafMean = 0;
  uint64_t trianglesPerLeafMax = 0;
  double sah = 0;  // SahSum with unit costs
  // SahSum with the seed's costs (seed 003: box 1, triangle 2; B8); NaN (null) for a seed that
  // has no such figure (seed 004).
  double sahSeed = 0;
  uint64_t bytes = 0;  // the memory image
  double buildSeconds = 0;
};

// Keys: triangles, nodes, leaves, empty_leaves, depth, list_entries, triangles_per_leaf_mean,
// triangles_per_leaf_max, sah, sah_seed, bytes, build_seconds (a NaN is null).
void to_json(nlohmann::json& json, const AccelQuality& quality);

}  // namespace rtu
