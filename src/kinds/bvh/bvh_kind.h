#pragma once
// Seed 003's BVH core as a core kind (rtu/core_kind.h), untimed for now: the golden traversal of
// bvh_traversal.h over the langr node layout, run by the untimed shell (rtu/golden_shell.h). The
// triangle test is the template parameter, chosen once at the top. Issue 28 registers the kind
// and adds its job set-up, timing and counters; what is here is what its golden model needs.

#include <cstdint>

#include "kinds/bvh/bvh_intersectors.h"
#include "kinds/bvh/bvh_traversal.h"
#include "kinds/bvh/langr_node.h"
#include "rtu/triangle_result.h"
#include "rtu/word_memory.h"

namespace rtu {

struct BvhConfig {
  // Entries: the seed's build stack has 64 (Alg. 3), its traversal's depth is unstated.
  int stackDepth = 64;
  ChildOrder childOrder = ChildOrder::Entry;
};

// One ray's outcome: the nearest hit (t along the ray's direction, the source triangle's id and
// barycentrics as geometry/triangle_tests.h), its cost in states, and what it counted.
using BvhResult = TriangleResult<float, BvhRayCounts>;

template <class Intersector>
struct BvhKind {
  static constexpr const char* kName = "bvh";
  using Job = BvhJob;
  using Result = BvhResult;
  using Behaviour = BvhTraversal<LangrNode, Intersector>;
  using Memory = WordMemory;
  using Config = BvhConfig;
  static constexpr int kWordsPerRead = Behaviour::kWordsPerRead;

  static Behaviour behaviour(const Config& config) {
    return Behaviour(config.stackDepth, config.childOrder);
  }
  static void start(Behaviour& traversal, const Job& job) { traversal.start(job); }
  static void writeResult(uint32_t idWord, const Behaviour& traversal, Result& result) {
    writeTriangleResult(idWord, traversal, result);
  }
};

}  // namespace rtu
