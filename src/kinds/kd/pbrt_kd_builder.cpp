#include "kinds/kd/pbrt_kd_builder.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "kinds/kd/introsort_2012.h"

namespace rtu {
namespace {

struct BoundEdge {
  float t = 0;
  uint32_t triangle = 0;
  bool start = false;
  bool flat = false;  // the triangle's box has no extent on the axis
};

// R1's BoundEdge::operator<: by t, and at equal t an END (type 1) before a START (type 0).
bool endFirst(const BoundEdge& a, const BoundEdge& b) {
  if (a.t == b.t) return !a.start && b.start;
  return a.t < b.t;
}

// PBRT v1's BoundEdge::operator<: by t, and at equal t a START (type 0) before an END (type 1).
bool startFirst(const BoundEdge& a, const BoundEdge& b) {
  if (a.t == b.t) return a.start && !b.start;
  return a.t < b.t;
}

// R1's order but for the triangles flat on the axis, whose edges go between the others' ENDs and
// STARTs, their START first: at equal t, other ENDs, flat STARTs, flat ENDs, other STARTs.
int flatKeptRank(const BoundEdge& e) { return e.flat ? (e.start ? 1 : 2) : (e.start ? 3 : 0); }
bool flatKept(const BoundEdge& a, const BoundEdge& b) {
  if (a.t == b.t) return flatKeptRank(a) < flatKeptRank(b);
  return a.t < b.t;
}

// The longest axis of the node, a tie to the later axis (R1's `d.x > d.y && d.x > d.z`).
int longestAxis(const glm::vec3& d) {
  if (d.x > d.y && d.x > d.z) return 0;
  return d.y > d.z ? 1 : 2;
}

struct Candidate {
  int axis = -1;
  size_t offset = 0;  // index into the axis's sorted edges
  float cost = INFINITY;
};

class Builder {
 public:
  Builder(const std::vector<Aabb<float>>& boxes, const PbrtKdParameters& parameters)
      : boxes_(boxes), p_(parameters) {}

  void build(KdBuild& out) {
    out_ = &out;
    std::vector<uint32_t> all(boxes_.size());
    for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    node(out.bounds, all, out.maxDepth, 0);
  }

 private:
  // Returns whether the subtree lists no triangle (an empty leaf).
  bool node(const Aabb<float>& bounds, const std::vector<uint32_t>& triangles, int depth,
            int badRefines) {
    const auto number = static_cast<uint32_t>(out_->nodes.size());
    out_->nodes.emplace_back();
    const auto n = static_cast<int>(triangles.size());
    if (n <= p_.maxTriangles || depth == 0) return leaf(number, triangles);
    const float oldCost = float(p_.intersectionCost) * float(n);
    const Candidate best = bestSplit(bounds, triangles);
    if (best.cost > oldCost) ++badRefines;
    if ((best.cost > 4.f * oldCost && n <= 16) || best.axis == -1 || badRefines == 3)
      return leaf(number, triangles);
    // The children's lists in sorted-edge order: STARTs before the split edge, ENDs after it.
    const std::vector<BoundEdge>& edges = edges_;
    std::vector<uint32_t> below, above;
    for (size_t i = 0; i < best.offset; ++i)
      if (edges[i].start) below.push_back(edges[i].triangle);
    for (size_t i = best.offset + 1; i < edges.size(); ++i)
      if (!edges[i].start) above.push_back(edges[i].triangle);
    const float split = edges[best.offset].t;
    KdBuildNode& inner = out_->nodes[number];
    inner.axis = best.axis;
    inner.split = split;
    inner.belowEmpty = below.empty();
    inner.aboveEmpty = above.empty();
    Aabb<float> belowBounds = bounds, aboveBounds = bounds;
    belowBounds.upper[best.axis] = aboveBounds.lower[best.axis] = split;
    const bool belowNone = node(belowBounds, below, depth - 1, badRefines);
    out_->nodes[number].above = static_cast<uint32_t>(out_->nodes.size());
    const bool aboveNone = node(aboveBounds, above, depth - 1, badRefines);
    if (!p_.pruneEmptyPairs) return false;
    if (belowNone && aboveNone) return prune(number);
    out_->nodes[number].belowEmpty = belowNone;
    out_->nodes[number].aboveEmpty = aboveNone;
    return false;
  }

  bool leaf(uint32_t number, const std::vector<uint32_t>& triangles) {
    KdBuildNode& leaf = out_->nodes[number];
    leaf.leaf = true;
    leaf.listIndex = static_cast<uint32_t>(out_->lists.size());
    leaf.count = static_cast<uint32_t>(triangles.size());
    out_->lists.insert(out_->lists.end(), triangles.begin(), triangles.end());
    return triangles.empty();
  }

  // The subtree at `number` lists no triangle: it becomes one empty leaf (its descendants, all
  // empty leaves or pruned, appended nothing to the lists).
  bool prune(uint32_t number) {
    out_->prunedNodes += 1;
    out_->nodes.resize(number + 1);
    out_->nodes[number] = KdBuildNode{};
    return leaf(number, {});
  }

  // The longest axis's cheapest candidate, or the next axes' when it has none; leaves edges_
  // sorted on the axis of the result (on the last tried when there is none).
  Candidate bestSplit(const Aabb<float>& bounds, const std::vector<uint32_t>& triangles) {
    const glm::vec3 d = bounds.upper - bounds.lower;
    const float totalArea = 2.f * (d.x * d.y + d.x * d.z + d.y * d.z);
    const float inverseArea = 1.f / totalArea;
    int axis = longestAxis(d);
    Candidate best;
    for (int retries = 0;; ++retries) {
      sortEdges(triangles, axis);
      sweep(bounds, d, inverseArea, axis, best);
      if (best.axis != -1 || retries == 2) return best;
      axis = (axis + 1) % 3;
    }
  }

  void sortEdges(const std::vector<uint32_t>& triangles, int axis) {
    edges_.clear();
    for (uint32_t t : triangles) {
      const bool flat = boxes_[t].lower[axis] == boxes_[t].upper[axis];
      edges_.push_back({boxes_[t].lower[axis], t, true, flat});
      edges_.push_back({boxes_[t].upper[axis], t, false, flat});
    }
    if (p_.edgeOrder == KdEdgeOrder::EndFirst)
      sort2012(edges_.begin(), edges_.end(), endFirst);
    else if (p_.edgeOrder == KdEdgeOrder::StartFirst)
      sort2012(edges_.begin(), edges_.end(), startFirst);
    else
      sort2012(edges_.begin(), edges_.end(), flatKept);
  }

  // Costs every edge strictly inside the node on `axis`, in R1's float32 operation order.
  void sweep(const Aabb<float>& bounds, const glm::vec3& d, float inverseArea, int axis,
             Candidate& best) const {
    const int other0 = axis == 0 ? 1 : 0, other1 = axis == 2 ? 1 : 2;
    const float lower = bounds.lower[axis], upper = bounds.upper[axis];
    int below = 0, above = static_cast<int>(edges_.size() / 2);
    for (size_t i = 0; i < edges_.size(); ++i) {
      if (!edges_[i].start) --above;
      const float t = edges_[i].t;
      if (t > lower && t < upper) {
        const float belowArea = 2 * (d[other0] * d[other1] + (t - lower) * (d[other0] + d[other1]));
        const float aboveArea = 2 * (d[other0] * d[other1] + (upper - t) * (d[other0] + d[other1]));
        const float pBelow = belowArea * inverseArea, pAbove = aboveArea * inverseArea;
        const float bonus = (above == 0 || below == 0) ? p_.emptyBonus : 0.f;
        const float cost =
            float(p_.traversalCost) + float(p_.intersectionCost) * (1.f - bonus) *
                                          (pBelow * float(below) + pAbove * float(above));
        if (cost < best.cost) best = Candidate{axis, i, cost};
      }
      if (edges_[i].start) ++below;
    }
  }

  const std::vector<Aabb<float>>& boxes_;
  PbrtKdParameters p_;
  KdBuild* out_ = nullptr;
  std::vector<BoundEdge> edges_;
};

}  // namespace

KdEdgeOrder parseKdEdgeOrder(const std::string& name) {
  if (name == "r1") return KdEdgeOrder::EndFirst;
  if (name == "pbrt") return KdEdgeOrder::StartFirst;
  if (name == "flat") return KdEdgeOrder::FlatKept;
  throw std::invalid_argument("accel.kd_edge_order '" + name + "': flat, pbrt or r1");
}

int pbrtMaxDepth(size_t triangles) {
  return static_cast<int>(std::round(8.f + 1.3f * std::log2(float(triangles))));
}

KdBuild buildPbrtKd(const std::vector<Aabb<float>>& boxes, const PbrtKdParameters& parameters) {
  if (boxes.empty()) throw std::invalid_argument("a k-d tree needs at least one triangle");
  KdBuild out;
  out.maxDepth = parameters.maxDepth > 0 ? parameters.maxDepth : pbrtMaxDepth(boxes.size());
  for (const Aabb<float>& box : boxes) out.bounds.merge(box);
  Builder(boxes, parameters).build(out);
  return out;
}

std::vector<Aabb<float>> pbrtTriangleBoxes(const std::vector<glm::dvec3>& corners) {
  std::vector<Aabb<float>> boxes(corners.size() / 3);
  for (size_t i = 0; i < corners.size(); ++i) boxes[i / 3].grow(glm::vec3(corners[i]));
  return boxes;
}

}  // namespace rtu
