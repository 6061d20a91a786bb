#pragma once
// Seed 001's k-d core as a core kind (rtu/core_kind.h; docs/triangles.md, "The k-d core"): the
// golden traversal of kd_traversal.h (SINT, NODE, TRAV, LIST, UTTM0-2, INT, POP with the short
// stack and restart) over the memory image of kd_image.h, its states' cycles from the shared
// triangle units' settings (kd_timing.h), rays set up from world-space ray records through a
// model header into the seed's hardware space (kd_job_setup.h), and its counters
// (kd_counters.h). The ray pipe's golden frame (raypipe/raypipe_golden.h) runs the same
// behaviour under the untimed shell with the pipe's settings.

#include <cstdint>
#include <string>
#include <vector>

#include "kinds/kd/kd_counters.h"
#include "kinds/kd/kd_job_setup.h"
#include "kinds/kd/kd_resources.h"
#include "kinds/kd/kd_traversal.h"
#include "rtu/core_kind.h"
#include "rtu/triangle_result.h"
#include "rtu/word_memory.h"

namespace rtu {

// One ray's outcome: the nearest hit (t along the ray's direction, the triangle's id in the
// scene's order and the seed's barycentrics: u weighs the triangle's A, v its B, so rtusim's
// (u, v) of geometry/triangle_tests.h are (v, 1 - u - v)), its cost in cycles, and what it
// counted.
using KdResult = TriangleResult<float, KdRayCounts>;

// The trace's names of KdState's codes, then BLOCKED.
inline const std::vector<std::string> kKdStateNames{"IDLE", "SINT",  "NODE",  "TRAV",
                                                    "LIST", "UTTM0", "UTTM1", "UTTM2",
                                                    "INT",  "POP",   "OUT",   "BLOCKED"};

struct KdKind : TriangleResultQueries<KdResult, KdCounters> {
  static constexpr const char* kName = "kd";
  static constexpr const char* kDescription =
      "k-d tree of seed 001 (the Tray Racer, PBRT v1's SAH build) over triangles with the short "
      "stack and restart, binary32";

  using Job = KdJob;
  using Result = KdResult;
  using Behaviour = KdTraversal;
  using Memory = WordMemory;
  using Config = KdTraversalConfig;

  static constexpr int kWordsPerRead = Behaviour::kWordsPerRead;
  static uint32_t stateCycles(const Behaviour& traversal) { return traversal.stateCycles(); }
  // Its ray/triangle unit (rtu/core_kind.h): the state that issues a test, the unit's interval.
  static bool issuesTriangleTest(const Behaviour& traversal) {
    return traversal.state() == KdState::Int;
  }
  static uint32_t triangleInterval(const Config& config) { return config.cycles.triangleInterval; }
  // Dispatched in D, SINT in D + 1 (no read, core.box.latency cycles), the root's NODE reads in
  // D + 2 at the earliest.
  static constexpr uint64_t kFirstReadAfterDispatch = 2;

  static constexpr uint64_t kIdleState = static_cast<uint64_t>(KdState::Idle);
  static constexpr uint64_t kOutState = static_cast<uint64_t>(KdState::Out);
  static constexpr uint64_t kBlockedState = static_cast<uint64_t>(KdState::Out) + 1;
  static StateVocabulary vocabulary() {
    return StateVocabulary{kKdStateNames, 4, kIdleState, kOutState, kBlockedState};
  }

  // The job manager's set-up of a world-space ray record (it takes no record of its own).
  class Setup : public KdJobSetup {
   public:
    Setup(WordMemory memory, const JobManagerTiming& timing, const Config&)
        : KdJobSetup(memory, timing) {}
  };

  static Behaviour behaviour(const Config& config) { return Behaviour(config); }
  static void start(Behaviour& traversal, const Job& job) { traversal.start(job); }
  static void writeResult(uint32_t idWord, const Behaviour& traversal, Result& result) {
    writeTriangleResult(idWord, traversal, result);
  }

  using Counters = KdCounters;
  static void count(const Behaviour& traversal, Counters& counters) {
    counters.add(traversal.counts());
  }

  // What the RTU's machinery asks of a result besides TriangleResultQueries' (rtu/core_kind.h),
  // the scene manager's: t is the parameter along the world-space ray (the model transform and
  // the swap into hardware space keep it), in the units of its direction, from 0.
  static bool hitAhead(const Result& result) { return result.hit && result.t >= 0; }
  static bool nearer(const Result& a, const Result& b) { return a.t < b.t; }
  static double hitDistance(const Result& result, const Config&) { return result.t; }
  // id, t, u, v, the triangle and the cost: six words, in the output link's 32-byte record.
  static uint64_t resultRecordBytes(const Config&) { return 32; }
};

}  // namespace rtu
