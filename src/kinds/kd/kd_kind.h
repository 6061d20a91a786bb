#pragma once
// Seed 001's k-d core as a core kind (rtu/core_kind.h), untimed for now: the golden traversal of
// kd_traversal.h over the memory image of kd_image.h, run by the untimed shell
// (rtu/golden_shell.h). Issue 28 registers the kind and adds its job set-up, timing and counters;
// what is here is what its golden model needs.

#include <cstdint>

#include "kinds/kd/kd_traversal.h"
#include "rtu/triangle_result.h"
#include "rtu/word_memory.h"

namespace rtu {

// One ray's outcome: the nearest hit (t along the ray's direction, the triangle's id in the
// scene's order and the seed's barycentrics: u weighs the triangle's A, v its B, so rtusim's
// (u, v) of geometry/triangle_tests.h are (v, 1 - u - v)), its cost in states, and what it
// counted.
using KdResult = TriangleResult<float, KdRayCounts>;

struct KdKind {
  static constexpr const char* kName = "kd";
  using Job = KdJob;
  using Result = KdResult;
  using Behaviour = KdTraversal;
  using Memory = WordMemory;
  using Config = KdTraversalConfig;
  static constexpr int kWordsPerRead = Behaviour::kWordsPerRead;

  static Behaviour behaviour(const Config& config) { return Behaviour(config); }
  static void start(Behaviour& traversal, const Job& job) { traversal.start(job); }
  static void writeResult(uint32_t idWord, const Behaviour& traversal, Result& result) {
    writeTriangleResult(idWord, traversal, result);
  }
};

}  // namespace rtu
