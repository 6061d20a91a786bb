#pragma once
// The registers of the per-cycle RTL top level (rtl_cycle_model.h) with cores of one kind: a
// template over the kind, chosen once by the host that makes it (runRtlTop, the scene manager's
// reference), so no call on the per-cycle path is virtual. Every cycle first computes all
// combinational signals from the registers (evaluate), then updates every register of every
// module (the clock functions), as the clock edge does.

#include <algorithm>
#include <cstdint>
#include <deque>
#include <vector>

#include "kinds/core_result.h"
#include "kinds/host_record.h"
#include "reference/rtl_cycle_model.h"
#include "rtu/job_manager_timing.h"
#include "rtu/word_memory.h"

namespace rtu {
namespace rtl_top {

constexpr int kJobManagerStages = 6;  // P_STAGES

// job_t: what the job manager hands to the cores, the id word and the kind's job (for SVO a, root,
// t0 and t1).
template <class Kind>
struct Job {
  uint64_t tag = 0;  // not an RTL signal: it names the job to the host
  uint32_t idWord = 0;
  typename Kind::Job job;
};

// The combinational signals of one cycle, named after the RTL's wires.
template <class Kind>
struct Wires {
  // host -> job_manager
  bool inValid = false;
  const RtlOffer* inRay = nullptr;
  bool pipelineEnable = false;
  bool inReady = false;
  // job_manager -> scheduler -> cores
  bool schedValid = false;
  bool schedReady = false;
  Job<Kind> pendingJob;
  std::vector<bool> coreInReady;
  std::vector<bool> coreInValid;
  // cores -> result_manager -> host
  std::vector<bool> coreOutValid;
  std::vector<bool> coreOutReady;
  std::vector<RtlCycle::Delivery> coreOutResult;
  // cores -> triangle units: the unit takes core i's test this cycle
  std::vector<bool> unitGrant;
  bool outValid = false;
  bool outReady = true;
  RtlCycle::Delivery outResult;
};

// C.2's valid_delay shift register and the job fields beside it, kept as the jobs in the pipeline
// with the cycles each still has to go: a t-value record goes P_STAGES, a ray record more
// (JobSetup). Every job moves one stage when pipeline_enable is high and none when it is low; a
// job reaches the output no earlier than the cycle after the one ahead of it. For t-value
// records alone this is exactly the shift register.
template <class Kind>
struct PipelineJob {
  Job<Kind> job;
  uint64_t remaining = 0;  // cycles to the output; 0: at the output (valid_delay[5])
};

template <class Kind>
struct JobManager {
  std::deque<PipelineJob<Kind>> pipeline;
  uint64_t fetchRemaining = 0;  // cycles of a model header fetch still to come
};

// A core slot: the kind's behaviour (for SVO core_state, the frames and the result fields), whose
// trace code tells IDLE and OUT (the kind's kIdleState and kOutState).
template <class Kind>
struct Core {
  typename Kind::Behaviour behaviour;
  uint32_t idWord = 0;  // out_result.job_id
  uint64_t tag = 0;
  uint32_t stateCycle = 0;  // cycles of the current state done (Kind::stateCycles, SVO: 1)
  bool testTaken = false;   // the current state's test went to the triangle unit

  uint64_t state() const { return static_cast<uint64_t>(behaviour.state()); }
  // Its state asks the triangle unit this cycle: it issues a test the unit has not taken yet.
  bool asksUnit() const {
    return state() != Kind::kIdleState && state() != Kind::kOutState && !testTaken &&
           issuesTriangleTest<Kind>(behaviour);
  }
};

// A ray/triangle unit shared by the cores [first, first + count): it takes one test in a cycle, no
// earlier than `interval` cycles after the last, from the first asking core at or after `turn`,
// counting on cyclically through the group.
struct TriangleUnit {
  int first = 0, count = 1;
  uint64_t freeFrom = 0;
  int turn = 0;
};

struct ResultManager {
  std::vector<bool> resultValid;
  std::vector<RtlCycle::Delivery> resultBuffer;
  int resultSelect = 0;
};

// core_select and result_select: count 0 .. count - 1 and wrap, every cycle.
inline int nextSelect(int select, int count) { return select < count - 1 ? select + 1 : 0; }

inline void recordCycle(std::vector<uint64_t>& cycles, uint64_t tag, uint64_t cycle) {
  if (cycles.size() <= tag) cycles.resize(tag + 1, 0);
  cycles[tag] = cycle;
}

}  // namespace rtl_top

// The cores are of the kind `Kind` (the kind `config.core` names, which the maker chose with
// withCoreKind).
template <class Kind>
class RtlTop {
 public:
  // Throws std::invalid_argument for an invalid configuration.
  RtlTop(const WordMemory& memory, const RtlTopConfig& config);
  RtlTop(const RtlTop&) = delete;
  RtlTop& operator=(const RtlTop&) = delete;

  // One cycle: the combinational signals with the host offering `offer` (null: in_valid low),
  // then the clock edge. Throws std::runtime_error for a model header that is not valid.
  RtlCycle step(const RtlOffer* offer);
  uint64_t cycle() const { return cycle_; }
  // By tag: the cycle each job was taken by the job manager, and handed to a core.
  const std::vector<uint64_t>& acceptCycles() const { return acceptCycles_; }
  const std::vector<uint64_t>& dispatchCycles() const { return dispatchCycles_; }

 private:
  using Wires = rtl_top::Wires<Kind>;
  using Job = rtl_top::Job<Kind>;
  using Core = rtl_top::Core<Kind>;
  Wires evaluate(const RtlOffer* offer) const;
  // Each clock function updates one module from the wires and its own registers only, so the
  // order in which they run does not matter.
  void clockJobManager(const Wires& wires);
  void clockScheduler();
  void clockCores(const Wires& wires);
  void clockUnits(const Wires& wires);
  void clockResultManager(const Wires& wires);
  // Which core, if any, `unit` takes a test from this cycle.
  int unitGrant(const rtl_top::TriangleUnit& unit) const;
  // The conversion is a pure function of the input, so converting on entry and carrying the
  // result down the stages gives what float_to_fixed delivers at the end of them.
  void accept(const RtlOffer& offer);

  WordMemory memory_;
  RtlTopConfig config_;
  typename Kind::Setup setup_;  // the kind's job set-up, with the model headers read so far
  rtl_top::JobManager<Kind> jobManager_;
  int coreSelect_ = 0;
  std::vector<Core> cores_;
  std::vector<rtl_top::TriangleUnit> units_;  // every kind has them; only a kind with tests asks
  uint32_t unitInterval_ = 1;
  rtl_top::ResultManager resultManager_;
  uint64_t cycle_ = 0;
  std::vector<uint64_t> acceptCycles_;
  std::vector<uint64_t> dispatchCycles_;
};

template <class Kind>
RtlTop<Kind>::RtlTop(const WordMemory& memory, const RtlTopConfig& config)
    : memory_(memory),
      config_(config),
      setup_(memory,
             JobManagerTiming{rtl_top::kJobManagerStages, config.rayStages,
                              config.headerFetchCycles},
             config.coreConfig<Kind>()) {
  config_.validate();
  const size_t cores = static_cast<size_t>(config_.cores);
  const Core idle{Kind::behaviour(config_.coreConfig<Kind>())};
  cores_.assign(cores, idle);
  for (int first = 0; first < config_.cores; first += config_.triangleSharedBy)
    units_.push_back({first, std::min(config_.triangleSharedBy, config_.cores - first), 0, first});
  unitInterval_ = triangleIntervalOf<Kind>(config_.coreConfig<Kind>());
  resultManager_.resultValid.assign(cores, false);
  resultManager_.resultBuffer.assign(cores, RtlCycle::Delivery{});
}

template <class Kind>
RtlCycle RtlTop<Kind>::step(const RtlOffer* offer) {
  const Wires wires = evaluate(offer);
  RtlCycle handshakes{cycle_, wires.inValid && wires.inReady, std::nullopt};
  if (wires.outValid && wires.outReady) handshakes.delivered = wires.outResult;
  if (handshakes.accepted) rtl_top::recordCycle(acceptCycles_, offer->tag, cycle_);
  clockJobManager(wires);
  clockScheduler();
  clockCores(wires);
  clockUnits(wires);
  clockResultManager(wires);
  ++cycle_;
  return handshakes;
}

template <class Kind>
typename RtlTop<Kind>::Wires RtlTop<Kind>::evaluate(const RtlOffer* offer) const {
  const size_t cores = cores_.size();
  Wires w;
  w.coreInReady.assign(cores, false);
  w.coreInValid.assign(cores, false);
  w.coreOutValid.assign(cores, false);
  w.coreOutReady.assign(cores, false);
  w.coreOutResult.assign(cores, RtlCycle::Delivery{});

  // svo_trav_core
  for (size_t i = 0; i < cores; ++i) {
    const Core& core = cores_[i];
    w.coreInReady[i] = core.state() == Kind::kIdleState;
    w.coreOutValid[i] = core.state() == Kind::kOutState;
    if (w.coreOutValid[i]) {
      w.coreOutResult[i].tag = core.tag;
      Kind::writeResult(core.idWord, core.behaviour,
                        emplaceResult<Kind>(w.coreOutResult[i].result));
    }
  }

  // triangle units
  w.unitGrant.assign(cores, false);
  for (const rtl_top::TriangleUnit& unit : units_) {
    const int granted = unitGrant(unit);
    if (granted >= 0) w.unitGrant[static_cast<size_t>(granted)] = true;
  }

  // result_manager
  const rtl_top::ResultManager& rm = resultManager_;
  for (size_t i = 0; i < cores; ++i) w.coreOutReady[i] = !rm.resultValid[i];
  w.outValid = rm.resultValid[rm.resultSelect];
  w.outResult = rm.resultBuffer[rm.resultSelect];

  // scheduler
  const rtl_top::JobManager<Kind>& jm = jobManager_;
  w.schedReady = w.coreInReady[coreSelect_];
  w.schedValid = !jm.pipeline.empty() && jm.pipeline.front().remaining == 0;
  for (size_t i = 0; i < cores; ++i)
    w.coreInValid[i] = w.schedValid && i == static_cast<size_t>(coreSelect_);

  // job_manager
  if (w.schedValid) w.pendingJob = jm.pipeline.front().job;
  w.pipelineEnable = w.schedReady || !w.schedValid;
  w.inReady = w.pipelineEnable && jm.fetchRemaining == 0;

  // host
  w.inValid = offer != nullptr;
  w.inRay = offer;
  w.outReady = true;
  return w;
}

template <class Kind>
int RtlTop<Kind>::unitGrant(const rtl_top::TriangleUnit& unit) const {
  if (cycle_ < unit.freeFrom) return -1;
  for (int k = 0; k < unit.count; ++k) {
    const int core = unit.first + (unit.turn - unit.first + k) % unit.count;
    if (cores_[static_cast<size_t>(core)].asksUnit()) return core;
  }
  return -1;
}

template <class Kind>
void RtlTop<Kind>::clockJobManager(const Wires& w) {
  rtl_top::JobManager<Kind>& jm = jobManager_;
  if (jm.fetchRemaining > 0) --jm.fetchRemaining;
  if (!w.pipelineEnable) return;
  if (w.schedValid) jm.pipeline.pop_front();  // enabled with a valid output: the core took it
  for (rtl_top::PipelineJob<Kind>& job : jm.pipeline) --job.remaining;
  if (w.inValid && w.inReady) accept(*w.inRay);
}

template <class Kind>
void RtlTop<Kind>::accept(const RtlOffer& offer) {
  const JobSetUp<typename Kind::Job> set = setUpHostRecord<Kind>(setup_, offer.record);
  const Job job{offer.tag, set.idWord, set.job};
  // In the pipeline from the next cycle, at the output `latency` cycles after this one.
  uint64_t remaining = set.latency - 1;
  if (!jobManager_.pipeline.empty())
    remaining = std::max(remaining, jobManager_.pipeline.back().remaining + 1);
  jobManager_.pipeline.push_back({job, remaining});
  jobManager_.fetchRemaining = set.headerFetch;
}

template <class Kind>
void RtlTop<Kind>::clockScheduler() {
  coreSelect_ = rtl_top::nextSelect(coreSelect_, config_.cores);
}

template <class Kind>
void RtlTop<Kind>::clockCores(const Wires& w) {
  const auto read = [this](uint32_t address) { return memory_.read(address); };
  for (size_t i = 0; i < cores_.size(); ++i) {
    Core& core = cores_[i];
    if (core.state() == Kind::kIdleState) {
      if (w.coreInReady[i] && w.coreInValid[i]) {
        const Job& job = w.pendingJob;
        core.idWord = job.idWord;
        core.tag = job.tag;
        Kind::start(core.behaviour, job.job);
        rtl_top::recordCycle(dispatchCycles_, job.tag, cycle_);
      }
    } else if (core.state() == Kind::kOutState) {
      if (w.coreOutReady[i]) core.behaviour.finish();
    } else if (core.asksUnit() && !w.unitGrant[i]) {
      // waits for its triangle unit: the state's cycles start with the grant
    } else {
      if (w.unitGrant[i]) core.testTaken = true;
      if (++core.stateCycle == Kind::stateCycles(core.behaviour)) {
        core.behaviour.step(read);  // in the state's last cycle
        core.stateCycle = 0;
        core.testTaken = false;
      }
    }
  }
}

template <class Kind>
void RtlTop<Kind>::clockUnits(const Wires& w) {
  for (rtl_top::TriangleUnit& unit : units_) {
    for (int core = unit.first; core < unit.first + unit.count; ++core) {
      if (!w.unitGrant[static_cast<size_t>(core)]) continue;
      unit.freeFrom = cycle_ + unitInterval_;
      unit.turn = core + 1 < unit.first + unit.count ? core + 1 : unit.first;
    }
  }
}

template <class Kind>
void RtlTop<Kind>::clockResultManager(const Wires& w) {
  rtl_top::ResultManager& rm = resultManager_;
  for (size_t i = 0; i < rm.resultValid.size(); ++i) {
    if (w.coreOutReady[i] && w.coreOutValid[i]) {
      rm.resultValid[i] = true;
      rm.resultBuffer[i] = w.coreOutResult[i];
    }
  }
  if (w.outReady && w.outValid) rm.resultValid[rm.resultSelect] = false;
  rm.resultSelect = rtl_top::nextSelect(rm.resultSelect, config_.cores);
}

}  // namespace rtu
