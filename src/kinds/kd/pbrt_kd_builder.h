#pragma once
// Seed 001's k-d tree builder: PBRT v1's KdTreeAccel SAH build (S1 §3.2 p.19 L379-389 says only
// "from PBRT"), as the team's software runs it (R1 SOFTWARE/src/scene/kdtree.cpp create_tree,
// at 81a34cd), so that its scene files can be reproduced byte for byte:
// - every bound and cost in float32, in R1's operation order (a triangle's box from its vertices
//   cast to float; R1 Triangle::WorldBound);
// - the split axis is the node's longest, a tie going to the later axis; only if that axis has no
//   candidate edge strictly inside the node is the next tried (at most twice);
// - edges sorted by position, an END before a START at equal positions (R1's comparator, changed
//   from PBRT's), by the unstable sort of R1's 2012 library (introsort_2012.h; reading K6); or,
//   with KdEdgeOrder::StartFirst, PBRT's own order (a START before an END);
// - cost = C_trav + C_isect (1 - bonus) (p_below n_below + p_above n_above), the bonus when a side
//   is empty; the strictly cheapest candidate wins;
// - a leaf when n <= maxTriangles or the depth budget is spent, or when no candidate exists, the
//   best cost exceeds 4 n C_isect with n <= 16, or the third split costlier than n C_isect on the
//   path (badRefines, counted along the path);
// - children's lists in sorted-edge order; nodes numbered depth first (below child = parent + 1);
//   leaves' lists concatenated in node order.
// The parameters are the team's (R1 SOFTWARE/src/raytracer/main.cpp L52-56, 173).

#include <cstdint>
#include <string>
#include <vector>

#include "geometry/aabb.h"

namespace rtu {

// The order of edges at equal positions (docs/triangles.md, "Edge order"). R1's (EndFirst) gives a
// triangle lying flat in the split plane, at the split, to neither child: it is in no leaf's
// list, so no ray finds it (on a voxel scene's faces most triangles: the sphere at depth 5 keeps
// 792 of 6,288). PBRT's (StartFirst) puts such a triangle below when the split is an END and above
// when it is a START, so every triangle is in some leaf.
// FlatKept is R1's order but for the flat triangles, whose START and END go between the others'
// ENDs and STARTs: every flat triangle is listed, and a triangle merely touching the plane goes to
// one side only, as in R1's (PBRT's puts it on both: the bunny's tree doubles).
enum class KdEdgeOrder : uint8_t { EndFirst, StartFirst, FlatKept };

struct PbrtKdParameters {
  int intersectionCost = 80;
  int traversalCost = 1;
  float emptyBonus = 0.1f;  // R1: ebonus_percent / 100.0 = 10 / 100.0, passed as float
  int maxTriangles = 2;
  int maxDepth = -1;  // -1: round(8 + 1.3 log2 N), PBRT's default
  // R1's order, so that its files are reproduced byte for byte; rtusim's own builds choose with
  // accel.kd_edge_order (FlatKept by default).
  KdEdgeOrder edgeOrder = KdEdgeOrder::EndFirst;
  // rtusim's correction, off to reproduce R1's files byte for byte. R1's edge order gives a
  // triangle lying flat in its node's split plane to neither child, so a node whose triangles all
  // lie so gets two empty children, and TRAV (which descends into the far child when the near one
  // is empty) then walks into an empty leaf, whose count the RTL's list path wraps (6-bit
  // lnum_left: 64 list entries tested). Pruned, such a node becomes an empty leaf itself (up the
  // tree while a parent's children are both empty), and its parent marks it empty, so no ray
  // reaches it.
  bool pruneEmptyPairs = true;
};

// "r1" -> EndFirst, "pbrt" -> StartFirst, "flat" -> FlatKept; throws std::invalid_argument naming
// accel.kd_edge_order for other text.
KdEdgeOrder parseKdEdgeOrder(const std::string& name);

// round(8 + 1.3f log2(float(N))) in float32: 18 for 200 triangles, 21 for 1023.
int pbrtMaxDepth(size_t triangles);

// A node in PBRT's terms: world axes (0 = x), the split as built (float32, untruncated).
struct KdBuildNode {
  bool leaf = false;
  int axis = 0;
  float split = 0;
  uint32_t above = 0;  // the above (high) child; the below child is this node + 1
  bool belowEmpty = false, aboveEmpty = false;
  uint32_t listIndex = 0, count = 0;  // a leaf's triangles: lists[listIndex, listIndex + count)
};

struct KdBuild {
  std::vector<KdBuildNode> nodes;  // depth first; nodes[0] is the root
  std::vector<uint32_t> lists;     // triangle ids, by leaf in node order
  Aabb<float> bounds;              // the union of the triangles' boxes
  int maxDepth = 0;
  uint32_t prunedNodes = 0;
};

// Builds over triangle boxes (triangle i's box is boxes[i]). Throws std::invalid_argument on no
// boxes. KdBuild::prunedNodes counts the interior nodes pruneEmptyPairs turned into empty leaves.
KdBuild buildPbrtKd(const std::vector<Aabb<float>>& boxes, const PbrtKdParameters& parameters);

// Triangle boxes as R1 forms them: each vertex coordinate cast to float, then the box of the
// three. `vertices` holds three per triangle, in double.
std::vector<Aabb<float>> pbrtTriangleBoxes(const std::vector<glm::dvec3>& corners);

}  // namespace rtu
