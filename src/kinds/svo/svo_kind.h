#pragma once
// The sparse voxel octree core of the thesis as a core kind (rtu/core_kind.h): what every timing
// shell and the shared machinery need to know of it, in one place.

#include <array>
#include <cstdint>

#include "kinds/svo/fixed_point.h"
#include "kinds/svo/golden_config.h"
#include "kinds/svo/job_setup.h"
#include "kinds/svo/state_vocabulary.h"
#include "kinds/svo/svo_counters.h"
#include "kinds/svo/svo_memory.h"
#include "kinds/svo/svo_resources.h"
#include "kinds/svo/thesis_records.h"
#include "kinds/svo/traversal_core.h"
#include "rtu/core_kind.h"
#include "rtu/job_manager_timing.h"

namespace rtu {

// What the job manager hands an SVO core (the RTL's job_t less the id word): the t-values in
// fixed point, the direction coefficient, the root's address and the ray's span.
struct SvoJob {
  uint8_t a = 0;
  std::array<int64_t, 3> t0{}, t1{};
  uint32_t root = 0;
  RaySpan span = RaySpan::Line;
};

struct SvoKind {
  static constexpr const char* kName = "svo";
  static constexpr const char* kDescription =
      "sparse voxel octree core of the thesis (Espe 2019), Q-format fixed point";

  // The kind's own record of a job, which a shell that sets its jobs up itself takes (the cache
  // warmer): the thesis driver's t-value record.
  using Record = TValueRecord;
  using Job = SvoJob;
  using Result = TraversalResult;
  using Behaviour = TraversalCore<FixedArith>;
  using Memory = WordMemory;
  using Config = GoldenConfig;

  // Memory accesses: each reading state reads one 32-bit word (a descriptor in EVAL, a far word
  // in PUSH), and every state takes one cycle.
  static constexpr int kWordsPerRead = 1;
  static constexpr uint32_t stateCycles(const Behaviour&) { return 1; }
  // Dispatched in D, INIT in D + 1, the first read in EVAL in D + 2: the memory arbiter's bound
  // on an idle core's next request (docs/cycle-semantics.md, "Run-ahead").
  static constexpr uint64_t kFirstReadAfterDispatch = 2;

  // Trace codes: CoreState's values, and one more for BLOCKED. Constants, since a timed core
  // records them on its hot path.
  static constexpr uint64_t kIdleState = static_cast<uint64_t>(CoreState::Idle);
  static constexpr uint64_t kOutState = static_cast<uint64_t>(CoreState::Out);
  static constexpr uint64_t kBlockedState = kBlockedStateCode;
  static StateVocabulary vocabulary() {
    return StateVocabulary{kCoreStateNames, 3, kIdleState, kOutState, kBlockedState};
  }

  // The job manager's set-up (thesis 6.2.1, appendix C.2) of either record the SVO core takes (a
  // t-value record or a world-space ray): through the pipeline of kinds/svo/job_setup.h, then its
  // t-values to fixed point (appendix C.2.1).
  class Setup {
   public:
    Setup(WordMemory memory, const JobManagerTiming& timing, const Config& config)
        : records_(memory, timing, config.epsilon), config_(config) {}
    JobSetUp<Job> setUp(const TValueRecord& record) { return converted(records_.setUp(record)); }
    // Throws std::runtime_error for a model header that is not valid.
    JobSetUp<Job> setUp(const RayRecord& record) { return converted(records_.setUp(record)); }

   private:
    JobSetUp<Job> converted(const JobSetup::SetUp& set) const {
      return {SvoKind::setUp(set.job, config_), set.job.idWord(), set.latency, set.headerFetch};
    }

    JobSetup records_;
    Config config_;
  };

  static Behaviour behaviour(const Config& config) {
    return Behaviour(FixedArith{config.format}, config.stackFrames);
  }
  // The job manager's set-up of a t-value record (appendix C.2.1: float32 to fixed point), also
  // for a shell that sets its jobs up itself (the cache warmer).
  static Job setUp(const Record& record, const Config& config) {
    return Job{record.a, convertToFixed(record.t0Bits, config.format, config.conversion),
               convertToFixed(record.t1Bits, config.format, config.conversion), record.root,
               record.span};
  }
  static void start(Behaviour& core, const Job& job) {
    core.start(job.t0, job.t1, job.a, job.root, job.span);
  }
  static void writeResult(uint32_t idWord, const Behaviour& core, Result& result) {
    rtu::writeResult(idWord, core, result);
  }

  // The kind's own counters, counted per job when its result is offered.
  using Counters = SvoCounters;
  static void count(const Behaviour& core, Counters& counters) {
    counters.stackOverflows += core.stackOverflow();
    counters.tOverflows += core.tOverflow();
    counters.anyHitRays += core.span() == RaySpan::AnyHit;
    counters.anyHitHits += core.span() == RaySpan::AnyHit && core.hit();
  }

  // What the RTU's kind-agnostic machinery asks of a result (rtu/core_kind.h lists them;
  // kinds/core_result.h asks them of a CoreKindResult). The recurrence's runs count the kind's
  // counters from the results, as a timed core counts them from the behaviour.
  static uint32_t resultIdWord(const Result& result) { return result.idWord; }
  static bool resultHit(const Result& result) { return result.hit; }
  static uint32_t resultCost(const Result& result) { return result.cost; }
  static void setResultCost(Result& result, uint32_t cost) { result.cost = cost; }
  static bool resultBelowResolution(const Result& result) { return result.belowResolution; }
  static void countResult(const Result& result, Counters& counters) {
    counters.stackOverflows += result.stackOverflow;
    counters.tOverflows += result.tOverflow;
    const bool anyHit = (result.idWord & kAnyHitBit) != 0;
    counters.anyHitRays += anyHit;
    counters.anyHitHits += anyHit && result.hit;
  }
  // The scene manager's: a ray's miss before any job returned, whether a hit lies ahead of the
  // ray's origin (t >= 0), which of two hits is nearer (t in fixed point, exactly) and how far
  // along the ray a hit lies, in the units of its direction (t in the job manager's format).
  static Result miss(uint32_t idWord) {
    Result result;
    result.idWord = idWord;
    return result;
  }
  static bool hitAhead(const Result& result) { return result.hit && result.tHit >= 0; }
  static bool nearer(const Result& a, const Result& b) { return a.tHit < b.tHit; }
  static double hitDistance(const Result& result, const Config& config) {
    return config.format.toDouble(result.tHit);
  }
  // The output link's record of a result (48 bytes over 32 bits).
  static uint64_t resultRecordBytes(const Config& config) {
    return rtu::resultRecordBytes(config.format.totalBits);
  }
};

}  // namespace rtu
