#pragma once
// Top-down BVH builders by the surface area heuristic, as production ray tracers build them (not
// a seed's): `binned` (the default of `rtusim build --accel bvh`, as Embree's and tinybvh's
// binned builders: on each of the three axes, min(bins, 4 + n / 20) bins over the extent of the
// node's n centres, Embree's count, so small nodes sweep few bins) and
// `sweep` (every split between consecutive centres on each axis: the best object split, slower).
// Unlike langr, a node may stay a leaf when splitting does not pay:
//   split cost  C_box + C_tri (A_left n_left + A_right n_right) / A_node
//   leaf cost   C_tri n
// and a node is a leaf when it holds at most maxLeafSize triangles and its leaf cost is not above
// its best split cost, or when it holds one triangle. A node over maxLeafSize whose centres all
// coincide is halved in reference order (counted as a forced median). Children are allocated as
// an adjacent pair after their parent's subtree so far (depth first, left first), and each split
// keeps the order of the references on either side.

#include <cstdint>

#include "geometry/accel_quality.h"
#include "geometry/triangle_mesh.h"
#include "kinds/bvh/build_primitives.h"
#include "kinds/bvh/build_tree.h"

namespace rtu {

enum class SahSplitSearch { Binned, Sweep };

struct SahBuilderConfig {
  SahSplitSearch search = SahSplitSearch::Binned;
  uint32_t bins = 32;  // binned only: the most bins of a node
  uint32_t maxLeafSize = 8;
  SahCosts costs{1.0, 1.0};
};

struct SahBuild {
  BuildTree tree;
  uint32_t forcedMedians = 0;
};

// Builds over any primitives (a tree's references index them). Throws std::invalid_argument for
// primitives checkPrimitives refuses, fewer than 2 bins or a maximum leaf size of 0.
SahBuild buildSah(const BuildPrimitives& primitives, const SahBuilderConfig& config = {});
// Over the mesh's triangles; also throws for a mesh buildPrimitives refuses.
SahBuild buildSah(const TriangleMesh& mesh, const SahBuilderConfig& config = {});

}  // namespace rtu
