#pragma once
// Seed 004's BIH core as a core kind (rtu/core_kind.h; docs/triangles.md, "The BIH core"): the
// golden traversal of bih_traversal.h (Table 3.1 and Listing A.3, plus the states feeding the
// intersection unit), its states' cycles from the pipelined triangle unit (bih_timing.h: S4
// §3.3 p.41 L537, 41 cycles at one test a cycle; the traversal never waits on a result, §3.4
// p.43 L566-568), rays set up from world-space ray records through a model header onto the
// image's grid (bih_job_setup.h), and its counters (bih_counters.h). The registry's kind is
// BihKind<>, whose kernel is the one the image's formats follow (ListingIntersector); BihKind
// over one kernel fixes it at compile time (the hand tests).

#include <cstdint>
#include <string>
#include <vector>

#include "kinds/bih/bih_config.h"
#include "kinds/bih/bih_counters.h"
#include "kinds/bih/bih_intersectors.h"
#include "kinds/bih/bih_job_setup.h"
#include "kinds/bih/bih_resources.h"
#include "kinds/bih/bih_traversal.h"
#include "rtu/core_kind.h"
#include "rtu/triangle_result.h"
#include "rtu/word_memory.h"

namespace rtu {

// One ray's outcome: the nearest hit (t in grid units, the source triangle's id, the seed's u and
// v), its cost in cycles, what it counted, and the hit's t along the world-space ray.
struct BihResult : TriangleResult<int64_t, BihRayCounts> {
  double distance = 0;  // GridRay::worldT(t) on a hit; 0 on a miss

  bool operator==(const BihResult& o) const {
    return TriangleResult::operator==(o) && distance == o.distance;
  }
  bool operator!=(const BihResult& o) const { return !(*this == o); }
};

// The trace's names of BihState's codes, then BLOCKED.
inline const std::vector<std::string> kBihStateNames{"IDLE", "AABB", "NODE",   "INNER", "PUSH",
                                                     "POP",  "LEAF", "TRI0",   "TRI1",  "TRI2",
                                                     "TEST", "OUT",  "BLOCKED"};

template <class Intersector = ListingIntersector>
struct BihKind : TriangleResultQueries<BihResult, BihCounters> {
  static constexpr const char* kName = "bih";
  static constexpr const char* kDescription =
      "bounding interval hierarchy of seed 004 (Hanika 2007) over triangles on an n-bit grid, "
      "fixed point";

  using Job = BihJob;
  using Result = BihResult;
  using Behaviour = BihTraversal<Intersector>;
  using Memory = WordMemory;
  using Config = BihConfig;

  static constexpr int kWordsPerRead = Behaviour::kWordsPerRead;
  static uint32_t stateCycles(const Behaviour& traversal) { return traversal.stateCycles(); }
  // Its ray/triangle unit (rtu/core_kind.h): the state that issues a test, the unit's interval.
  static bool issuesTriangleTest(const Behaviour& traversal) {
    return traversal.state() == BihState::Test;
  }
  static uint32_t triangleInterval(const Config& config) { return config.cycles.triangleInterval; }
  // Dispatched in D, AABB in D + 1 (no read), the root's NODE reads in D + 2.
  static constexpr uint64_t kFirstReadAfterDispatch = 2;

  static constexpr uint64_t kIdleState = static_cast<uint64_t>(BihState::Idle);
  static constexpr uint64_t kOutState = static_cast<uint64_t>(BihState::Out);
  static constexpr uint64_t kBlockedState = static_cast<uint64_t>(BihState::Out) + 1;
  static StateVocabulary vocabulary() {
    return StateVocabulary{kBihStateNames, 4, kIdleState, kOutState, kBlockedState};
  }

  // The job manager's set-up of a world-space ray record (it takes no record of its own).
  class Setup : public BihJobSetup {
   public:
    Setup(WordMemory memory, const JobManagerTiming& timing, const Config&)
        : BihJobSetup(memory, timing) {}
  };

  static Behaviour behaviour(const Config& config) {
    return Behaviour(config.earlyOut, config.cycles);
  }
  static void start(Behaviour& traversal, const Job& job) { traversal.start(job); }
  static void writeResult(uint32_t idWord, const Behaviour& traversal, Result& result) {
    writeTriangleResult(idWord, traversal, result);
    result.distance = result.hit ? traversal.worldT() : 0;
  }

  using Counters = BihCounters;
  static void count(const Behaviour& traversal, Counters& counters) {
    counters.add(traversal.counts());
  }

  // What the RTU's machinery asks of a result besides TriangleResultQueries' (rtu/core_kind.h),
  // the scene manager's: a grid t is in its own model's grid units, so instances compare by the
  // distance along the world-space ray (the model transform keeps its parameter), from 0.
  static bool hitAhead(const Result& result) { return result.hit && result.distance >= 0; }
  static bool nearer(const Result& a, const Result& b) { return a.distance < b.distance; }
  static double hitDistance(const Result& result, const Config&) { return result.distance; }
  // id, t (n + 1 bits), u and v (m + E bits: two words each), the triangle, the distance in
  // float32 and the cost: nine words, in a 48-byte record on the output link.
  static uint64_t resultRecordBytes(const Config&) { return 48; }
};

}  // namespace rtu
