#pragma once
// The binned-SAH BVH builder of seed 003 (Langr 2016, section 3.4, Algorithms 3 and 4, lines
// 745-825), transcribed step for step so the tree, its node numbering and its reference order are
// the seed's. Where the pseudocode is silent or inconsistent, the readings B1-B7 of
// docs/triangles.md decide; each is named where it applies (langr_builder.cpp).

#include <cstdint>

#include "geometry/accel_quality.h"
#include "geometry/triangle_mesh.h"
#include "kinds/bvh/build_primitives.h"
#include "kinds/bvh/build_tree.h"

namespace rtu {

// The seed's settings (section 4.3, lines 863-865; the same in 4.4 and 4.5).
struct LangrConfig {
  uint32_t bins = 16;
  // A node with at most this many triangles is a leaf (Alg. 3 L774-778); the root is a leaf
  // below it (L751, B4).
  uint32_t leafThreshold = 10;
  // C_t (box) = 1, C_i (triangle) = 2: unused by Algorithm 4, whose SAH has no costs; they
  // weigh the seed's SAH figure (accel_quality.h, sah_seed, B8).
  SahCosts costs{1.0, 2.0};
};

struct LangrBuild {
  BuildTree tree;
  // Splits of nodes whose triangle centres all coincide, where Algorithm 4 would divide by zero;
  // each split its references in half instead (B2).
  uint32_t forcedMedians = 0;
  // The most nodes ever waiting on the build stack (the seed's fixed 64 entries, B5).
  uint32_t maxPendingNodes = 0;
};

// Builds the tree over all of `mesh`'s triangles. Throws std::invalid_argument for a mesh without
// triangles or with more than 2^32 - 1, a vertex index out of range, a coordinate that is not
// finite or beyond 2^1000 in magnitude (the binning arithmetic must not overflow), or a config with
// fewer than 2 bins or a leaf threshold of 0 (either would never end).
LangrBuild buildLangr(const TriangleMesh& mesh, const LangrConfig& config = {});
// The same over any primitives (a tree's references index them): throws for primitives
// checkPrimitives refuses or a config as above.
LangrBuild buildLangr(const BuildPrimitives& primitives, const LangrConfig& config = {});

}  // namespace rtu
