#pragma once
// Seed 003's BVH core as a core kind (rtu/core_kind.h; docs/triangles.md, "The BVH core"): the
// traversal of bvh_traversal.h over the langr node layout, its states' cycles from the box and
// triangle units' settings (bvh_timing.h), rays set up from world-space ray records through a
// model header (bvh_job_setup.h), and its counters (bvh_counters.h). The registry's kind is
// BvhKind<> (kinds/registry.h), whose triangle test is a setting (SelectedIntersector); BvhKind
// over one intersector fixes it at compile time (the two-level traversal, the benchmarks).

#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "kinds/bvh/bvh_config.h"
#include "kinds/bvh/bvh_counters.h"
#include "kinds/bvh/bvh_intersectors.h"
#include "kinds/bvh/bvh_job_setup.h"
#include "kinds/bvh/bvh_resources.h"
#include "kinds/bvh/bvh_traversal.h"
#include "kinds/bvh/langr_node.h"
#include "rtu/core_kind.h"
#include "rtu/triangle_result.h"
#include "rtu/word_memory.h"

namespace rtu {

// One ray's outcome: the nearest hit (t along the ray's direction, the source triangle's id and
// barycentrics as geometry/triangle_tests.h), its cost in cycles, and what it counted.
using BvhResult = TriangleResult<float, BvhRayCounts>;

// The trace's names of BvhState's codes, then BLOCKED.
inline const std::vector<std::string> kBvhStateNames{
    "IDLE",   "ROOT0", "ROOT1", "ROOT_TEST", "LEFT0", "LEFT1", "RIGHT0", "RIGHT1",
    "DECIDE", "REF",   "TRI0",  "TRI1",      "TRI2",  "TEST",  "INST0",  "INST1",
    "INST2",  "INST3", "INST4", "XFORM",     "POP",   "OUT",   "BLOCKED"};

template <class Intersector = SelectedIntersector>
struct BvhKind : TriangleResultQueries<BvhResult, BvhCounters> {
  static constexpr const char* kName = "bvh";
  static constexpr const char* kDescription =
      "bounding volume hierarchy of seed 003 (Langr 2016) over triangles, float32";

  using Job = BvhJob;
  using Result = BvhResult;
  using Behaviour = BvhTraversal<LangrNode, Intersector>;
  using Memory = WordMemory;
  using Config = BvhConfig;

  static constexpr int kWordsPerRead = Behaviour::kWordsPerRead;
  static uint32_t stateCycles(const Behaviour& traversal) { return traversal.stateCycles(); }
  // Its ray/triangle unit (rtu/core_kind.h): the state that issues a test, the unit's interval.
  static bool issuesTriangleTest(const Behaviour& traversal) {
    return traversal.state() == BvhState::Test;
  }
  static uint32_t triangleInterval(const Config& config) { return config.cycles.triangleInterval; }
  // Dispatched in D, ROOT0 reads in D + 1.
  static constexpr uint64_t kFirstReadAfterDispatch = 1;

  static constexpr uint64_t kIdleState = static_cast<uint64_t>(BvhState::Idle);
  static constexpr uint64_t kOutState = static_cast<uint64_t>(BvhState::Out);
  static constexpr uint64_t kBlockedState = static_cast<uint64_t>(BvhState::Out) + 1;
  static StateVocabulary vocabulary() {
    return StateVocabulary{kBvhStateNames, 5, kIdleState, kOutState, kBlockedState};
  }

  // The job manager's set-up of a world-space ray record (it takes no record of its own).
  class Setup : public BvhJobSetup {
   public:
    Setup(WordMemory memory, const JobManagerTiming& timing, const Config&)
        : BvhJobSetup(memory, timing) {}
  };

  static Behaviour behaviour(const Config& config) {
    return Behaviour(config.stackDepth, config.childOrder, config.cycles, intersector(config));
  }
  static void start(Behaviour& traversal, const Job& job) { traversal.start(job); }
  static void writeResult(uint32_t idWord, const Behaviour& traversal, Result& result) {
    writeTriangleResult(idWord, traversal, result);
  }

  using Counters = BvhCounters;
  static void count(const Behaviour& traversal, Counters& counters) {
    counters.add(traversal.counts());
  }

  // What the RTU's machinery asks of a result besides TriangleResultQueries' (rtu/core_kind.h),
  // the scene manager's: t is the parameter along the world-space ray (the model transform keeps
  // it), in the units of its direction, from 0.
  static bool hitAhead(const Result& result) { return result.hit && result.t >= 0; }
  static bool nearer(const Result& a, const Result& b) { return a.t < b.t; }
  static double hitDistance(const Result& result, const Config&) { return result.t; }
  // id, t, u, v, the triangle and the cost: six words, in the output link's 32-byte record.
  static uint64_t resultRecordBytes(const Config&) { return 32; }

 private:
  static Intersector intersector(const Config& config) {
    if constexpr (std::is_same_v<Intersector, SelectedIntersector>)
      return SelectedIntersector(config.triangleTest);
    else
      return Intersector{};
  }
};

}  // namespace rtu
