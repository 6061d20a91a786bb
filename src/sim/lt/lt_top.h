#pragma once
// The loosely-timed RTU (docs/fidelity.md, "The loosely-timed model"): thesis figure 6.1 with
// its memory at transaction level. N cores of one kind (LtTop<Kind>, chosen once by the caller:
// run/lt_simulation.cpp) are TLM-2.0 initiators; their memory is the ideal ROM (DMI) or, per core,
// an L1 target in front of the shared L2 target and the DRAM target.
//
// One thread drives them, temporally decoupled (tlm_utils::tlm_quantumkeeper, after the
// Accellera lt_td_initiator example): the job manager, scheduler and result manager are the
// recurrence of src/rtu/rtu_recurrence.h, the same rules as the cycle-accurate modules; at each
// dispatch the chosen core traverses its job through its memory at once, and the thread
// synchronises with the kernel whenever the dispatches run a quantum ahead of simulated time.
// Jobs are dispatched in cycle order, so the per-core L1s see their reads in cycle order; the
// shared L2 and DRAM see one traversal's reads after another's, out of cycle order by up to a
// traversal, and take them in their out-of-order form (src/sim/memory/resource_booking.h).

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <systemc>
#include <tlm>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "kinds/core_result.h"
#include "kinds/host_stream.h"
#include "rtu/rtu_recurrence.h"
#include "sim/ca/rtu_payloads.h"
#include "sim/lt/lt_core.h"
#include "sim/lt/lt_dram.h"
#include "sim/lt/lt_l1_cache.h"
#include "sim/lt/lt_l2_cache.h"
#include "sim/lt/lt_rom.h"
#include "sim/rtu_config.h"

namespace rtu {

// Told each job's result as it reaches the host, in the host's order: its cycles, the result and
// its cycles BLOCKED on memory.
using LtArrival =
    std::function<void(const JobCycles& cycles, const CoreKindResult& result, uint32_t blocked)>;

// What does not depend on the cores' kind: the memory targets, the job set-up, the recurrence and
// the quantum. The cores are LtTop's, reached once per dispatch through traverseOn. A job's
// result is held from its traversal until it drains to the host (`arrived`): the top holds the
// jobs in flight, not the frame.
class LtTopBase : public sc_core::sc_module {
 public:
  // After the simulation: the cycles and the result buffers' most.
  const RecurrenceTotals& totals() const { return totals_; }
  // Per core, the cycles its tests waited for a shared triangle unit.
  const std::vector<uint64_t>& unitStalls() const { return stalls_; }
  bool idealMemory() const { return rom_ != nullptr; }
  std::vector<CacheStats> l1Statistics() const;
  L2Stats l2Statistics() const;  // the L2's counts with the DRAM target's

 protected:
  // `records` must outlive the top; `accessBytes` is a core's access (what the ROM and an L1
  // serve).
  LtTopBase(sc_core::sc_module_name name, const RtuConfig& config, WordMemory memory,
            RecordSource records, LtArrival arrived, uint32_t accessBytes);

  // Binds a core's socket to its memory: the ROM, or an L1 of its own in front of the L2.
  void bindCore(tlm::tlm_initiator_socket<>& socket);
  const LtTime& time() const { return time_; }
  // Core `core`'s shared triangle unit, or null when the cores do not share them.
  LtTriangleUnit* triangleUnitOf(int core) {
    return units_.empty() ? nullptr : &units_[static_cast<size_t>(core / config_.triangleSharedBy)];
  }
  // The next job's result, of `Kind`, for its core to write.
  template <class Kind>
  typename Kind::Result& nextResult() {
    return inFlight_.emplace_back().result.template emplace<typename Kind::Result>();
  }

  // Runs `job` on core `core` from its first state in `initCycle`, writing nextResult().
  virtual LtTraversal traverseOn(int core, const CoreJob& job, uint64_t initCycle) = 0;

 private:
  // A job's result from its traversal until it drains.
  struct InFlight {
    CoreKindResult result;
    uint32_t blocked = 0;
    bool drained = false;
  };

  void drive();
  JobTiming setUp(size_t job);
  uint64_t traverse(size_t job, int core, uint64_t initCycle);
  void drained(const JobCycles& cycles);

  const RtuConfig& config_;
  const RecordSource records_;  // a vector's outlives the top
  const LtArrival arrived_;
  WordMemory memory_;
  uint32_t accessBytes_;
  LtTime time_;
  CoreJobSetup setup_;  // the kind's (kinds/registry.h): one call per job
  tlm_utils::tlm_quantumkeeper quantum_;
  std::unique_ptr<LtRom> rom_;
  std::vector<std::unique_ptr<LtL1Cache>> l1_;
  std::unique_ptr<LtL2Cache> l2_;
  std::unique_ptr<LtDram> dram_;
  CoreJob current_;  // the job set up last
  RecurrenceTotals totals_;
  std::deque<InFlight> inFlight_;  // jobs from firstInFlight_ on, up to the last dispatched
  size_t firstInFlight_ = 0;
  std::vector<LtTriangleUnit> units_;  // shared triangle units, by group (none: a unit a core)
  std::vector<uint64_t> stalls_;       // per core
};

template <class Kind>
class LtTop final : public LtTopBase {
 public:
  // `records` must outlive the top.
  LtTop(sc_core::sc_module_name name, const RtuConfig& config, WordMemory memory,
        RecordSource records, LtArrival arrived)
      : LtTopBase(name, config, memory, std::move(records), std::move(arrived),
                  4 * Kind::kWordsPerRead),
        behaviour_(Kind::behaviour(config.coreConfig<Kind>())) {
    for (int i = 0; i < config.cores; ++i) {
      cores_.push_back(std::make_unique<LtCore<Kind>>(("core_" + std::to_string(i)).c_str(),
                                                      behaviour_, time(), triangleUnitOf(i)));
      bindCore(cores_.back()->memory);
    }
  }

 private:
  LtTraversal traverseOn(int core, const CoreJob& job, uint64_t initCycle) override {
    // The job manager set the job up for this kind: no check (std::get would test and throw).
    return cores_[static_cast<size_t>(core)]->traverse(
        job.idWord, *std::get_if<typename Kind::Job>(&job.job), initCycle,
        this->template nextResult<Kind>());
  }

  // The cores' shared behaviour: each runs a job to its end in one call (lt_core.h).
  typename Kind::Behaviour behaviour_;
  std::vector<std::unique_ptr<LtCore<Kind>>> cores_;
};

}  // namespace rtu
