#pragma once
// Seed 004's BIH core as a core kind (rtu/core_kind.h), untimed for now: the golden traversal of
// bih_traversal.h, run by the untimed shell (rtu/golden_shell.h), with the kernel chosen once at
// the top. Issue 28 registers the kind and adds its job set-up (clip to the box, quantise),
// timing and counters; what is here is what its golden model needs.

#include <cstdint>

#include "kinds/bih/bih_intersectors.h"
#include "kinds/bih/bih_traversal.h"
#include "rtu/triangle_result.h"
#include "rtu/word_memory.h"

namespace rtu {

struct BihConfig {
  bool earlyOut = false;  // S4 §3.4 L577: not implemented in the seed; an option here
};

// One ray's outcome: the nearest hit (t in grid units, the source triangle's id, the seed's u and
// v), its cost in states, and what it counted.
using BihResult = TriangleResult<int64_t, BihRayCounts>;

template <class Intersector>
struct BihKind {
  static constexpr const char* kName = "bih";
  using Job = BihJob;
  using Result = BihResult;
  using Behaviour = BihTraversal<Intersector>;
  using Memory = WordMemory;
  using Config = BihConfig;
  static constexpr int kWordsPerRead = Behaviour::kWordsPerRead;

  static Behaviour behaviour(const Config& config) { return Behaviour(config.earlyOut); }
  static void start(Behaviour& traversal, const Job& job) { traversal.start(job); }
  static void writeResult(uint32_t idWord, const Behaviour& traversal, Result& result) {
    writeTriangleResult(idWord, traversal, result);
  }
};

}  // namespace rtu
