#include "reference/rtl_cycle_model.h"

#include <algorithm>
#include <deque>
#include <stdexcept>
#include <string>

#include "kinds/core_result.h"
#include "kinds/registry.h"

namespace rtu {

void RtlTopConfig::validate() const {
  if (cores < 1 || cores > kMaxRtlCores)
    throw std::invalid_argument("core count must be 1 to " + std::to_string(kMaxRtlCores) +
                                ", got " + std::to_string(cores));
  CoreKinds::validateConfigs(coreConfigs);
  if (rayStages < 0 || rayStages > 64 || headerFetchCycles < 0)
    throw std::invalid_argument("ray stages must be 0 to 64 and header fetch cycles not negative, "
                                "got " +
                                std::to_string(rayStages) + " and " +
                                std::to_string(headerFetchCycles));
}

namespace {

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

  uint64_t state() const { return static_cast<uint64_t>(behaviour.state()); }
};

struct ResultManager {
  std::vector<bool> resultValid;
  std::vector<RtlCycle::Delivery> resultBuffer;
  int resultSelect = 0;
};

// core_select and result_select: count 0 .. count - 1 and wrap, every cycle.
int nextSelect(int select, int count) { return select < count - 1 ? select + 1 : 0; }

void recordCycle(std::vector<uint64_t>& cycles, uint64_t tag, uint64_t cycle) {
  if (cycles.size() <= tag) cycles.resize(tag + 1, 0);
  cycles[tag] = cycle;
}

}  // namespace

// What RtlTop needs of the registers of any kind. One call per simulated cycle of the whole
// RTU, not per core: the cores' per-cycle work inside is a template over the kind.
class RtlTop::Registers {
 public:
  virtual ~Registers() = default;
  virtual RtlCycle step(const RtlOffer* offer) = 0;

  uint64_t cycle = 0;
  std::vector<uint64_t> acceptCycles;
  std::vector<uint64_t> dispatchCycles;
};

template <class Kind>
class RtlTop::KindRegisters final : public RtlTop::Registers {
 public:
  KindRegisters(const WordMemory& memory, const RtlTopConfig& config);

  RtlCycle step(const RtlOffer* offer) override;

 private:
  using Wires = rtu::Wires<Kind>;
  Wires evaluate(const RtlOffer* offer) const;
  // Each clock function updates one module from the wires and its own registers only, so the
  // order in which they run does not matter.
  void clockJobManager(const Wires& wires);
  void clockScheduler();
  void clockCores(const Wires& wires);
  void clockResultManager(const Wires& wires);
  // The conversion is a pure function of the input, so converting on entry and carrying the
  // result down the stages gives what float_to_fixed delivers at the end of them.
  void accept(const RtlOffer& offer);

  WordMemory memory_;
  RtlTopConfig config_;
  typename Kind::Setup setup_;  // the kind's job set-up, with the model headers read so far
  JobManager<Kind> jobManager_;
  int coreSelect_ = 0;
  std::vector<Core<Kind>> cores_;
  ResultManager resultManager_;
};

template <class Kind>
RtlTop::KindRegisters<Kind>::KindRegisters(const WordMemory& memory, const RtlTopConfig& config)
    : memory_(memory),
      config_(config),
      setup_(memory,
             JobManagerTiming{kJobManagerStages, config.rayStages, config.headerFetchCycles},
             config.coreConfig<Kind>()) {
  config_.validate();
  const size_t cores = static_cast<size_t>(config_.cores);
  const Core<Kind> idle{Kind::behaviour(config_.coreConfig<Kind>())};
  cores_.assign(cores, idle);
  resultManager_.resultValid.assign(cores, false);
  resultManager_.resultBuffer.assign(cores, RtlCycle::Delivery{});
}

template <class Kind>
RtlCycle RtlTop::KindRegisters<Kind>::step(const RtlOffer* offer) {
  const Wires wires = evaluate(offer);
  RtlCycle handshakes{cycle, wires.inValid && wires.inReady, std::nullopt};
  if (wires.outValid && wires.outReady) handshakes.delivered = wires.outResult;
  if (handshakes.accepted) recordCycle(acceptCycles, offer->tag, cycle);
  clockJobManager(wires);
  clockScheduler();
  clockCores(wires);
  clockResultManager(wires);
  ++cycle;
  return handshakes;
}

template <class Kind>
typename RtlTop::KindRegisters<Kind>::Wires RtlTop::KindRegisters<Kind>::evaluate(
    const RtlOffer* offer) const {
  const size_t cores = cores_.size();
  Wires w;
  w.coreInReady.assign(cores, false);
  w.coreInValid.assign(cores, false);
  w.coreOutValid.assign(cores, false);
  w.coreOutReady.assign(cores, false);
  w.coreOutResult.assign(cores, RtlCycle::Delivery{});

  // svo_trav_core
  for (size_t i = 0; i < cores; ++i) {
    const Core<Kind>& core = cores_[i];
    w.coreInReady[i] = core.state() == Kind::kIdleState;
    w.coreOutValid[i] = core.state() == Kind::kOutState;
    if (w.coreOutValid[i]) {
      w.coreOutResult[i].tag = core.tag;
      Kind::writeResult(core.idWord, core.behaviour,
                        emplaceResult<Kind>(w.coreOutResult[i].result));
    }
  }

  // result_manager
  const ResultManager& rm = resultManager_;
  for (size_t i = 0; i < cores; ++i) w.coreOutReady[i] = !rm.resultValid[i];
  w.outValid = rm.resultValid[rm.resultSelect];
  w.outResult = rm.resultBuffer[rm.resultSelect];

  // scheduler
  const JobManager<Kind>& jm = jobManager_;
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
void RtlTop::KindRegisters<Kind>::clockJobManager(const Wires& w) {
  JobManager<Kind>& jm = jobManager_;
  if (jm.fetchRemaining > 0) --jm.fetchRemaining;
  if (!w.pipelineEnable) return;
  if (w.schedValid) jm.pipeline.pop_front();  // enabled with a valid output: the core took it
  for (PipelineJob<Kind>& job : jm.pipeline) --job.remaining;
  if (w.inValid && w.inReady) accept(*w.inRay);
}

template <class Kind>
void RtlTop::KindRegisters<Kind>::accept(const RtlOffer& offer) {
  const JobSetUp<typename Kind::Job> set = setUpHostRecord<Kind>(setup_, offer.record);
  const Job<Kind> job{offer.tag, set.idWord, set.job};
  // In the pipeline from the next cycle, at the output `latency` cycles after this one.
  uint64_t remaining = set.latency - 1;
  if (!jobManager_.pipeline.empty())
    remaining = std::max(remaining, jobManager_.pipeline.back().remaining + 1);
  jobManager_.pipeline.push_back({job, remaining});
  jobManager_.fetchRemaining = set.headerFetch;
}

template <class Kind>
void RtlTop::KindRegisters<Kind>::clockScheduler() {
  coreSelect_ = nextSelect(coreSelect_, config_.cores);
}

template <class Kind>
void RtlTop::KindRegisters<Kind>::clockCores(const Wires& w) {
  const auto read = [this](uint32_t address) { return memory_.read(address); };
  for (size_t i = 0; i < cores_.size(); ++i) {
    Core<Kind>& core = cores_[i];
    if (core.state() == Kind::kIdleState) {
      if (w.coreInReady[i] && w.coreInValid[i]) {
        const Job<Kind>& job = w.pendingJob;
        core.idWord = job.idWord;
        core.tag = job.tag;
        Kind::start(core.behaviour, job.job);
        recordCycle(dispatchCycles, job.tag, cycle);
      }
    } else if (core.state() == Kind::kOutState) {
      if (w.coreOutReady[i]) core.behaviour.finish();
    } else if (++core.stateCycle == Kind::stateCycles(core.behaviour)) {
      core.behaviour.step(read);  // in the state's last cycle
      core.stateCycle = 0;
    }
  }
}

template <class Kind>
void RtlTop::KindRegisters<Kind>::clockResultManager(const Wires& w) {
  ResultManager& rm = resultManager_;
  for (size_t i = 0; i < rm.resultValid.size(); ++i) {
    if (w.coreOutReady[i] && w.coreOutValid[i]) {
      rm.resultValid[i] = true;
      rm.resultBuffer[i] = w.coreOutResult[i];
    }
  }
  if (w.outReady && w.outValid) rm.resultValid[rm.resultSelect] = false;
  rm.resultSelect = nextSelect(rm.resultSelect, config_.cores);
}

RtlTop::RtlTop(const WordMemory& memory, const RtlTopConfig& config)
    : registers_(withCoreKind(config.core, [&](auto kind) -> std::unique_ptr<Registers> {
        return std::make_unique<KindRegisters<decltype(kind)>>(memory, config);
      })) {}
RtlTop::~RtlTop() = default;

RtlCycle RtlTop::step(const RtlOffer* offer) { return registers_->step(offer); }
uint64_t RtlTop::cycle() const { return registers_->cycle; }
const std::vector<uint64_t>& RtlTop::acceptCycles() const { return registers_->acceptCycles; }
const std::vector<uint64_t>& RtlTop::dispatchCycles() const { return registers_->dispatchCycles; }

// The thesis' host: job i + 1 offered from the cycle after job i was taken.
RtlTopRun runRtlTop(const WordMemory& memory, const std::vector<HostRecord>& records,
                    const RtlTopConfig& config) {
  checkCoreTakes(config.core, records);
  RtlTop top(memory, config);
  RtlTopRun run;
  size_t next = 0;
  while (run.results.size() < records.size()) {
    std::optional<RtlOffer> offer;
    if (next < records.size()) offer = RtlOffer{records[next], next};
    const RtlCycle cycle = top.step(offer ? &*offer : nullptr);
    if (cycle.accepted) ++next;
    if (cycle.delivered) {
      run.results.push_back(cycle.delivered->result);
      run.resultCycles.push_back(cycle.cycle);
    }
  }
  run.acceptCycles = top.acceptCycles();
  run.dispatchCycles = top.dispatchCycles();
  run.totalCycles = top.cycle();
  return run;
}

RtlTopRun runRtlTop(const WordMemory& memory, const std::vector<TValueRecord>& jobs,
                    const RtlTopConfig& config) {
  return runRtlTop(memory, std::vector<HostRecord>(jobs.begin(), jobs.end()), config);
}

}  // namespace rtu
