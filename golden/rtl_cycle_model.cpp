#include "rtl_cycle_model.h"

#include <array>
#include <stdexcept>
#include <string>

#include "traversal_core.h"

namespace rtu {

void RtlTopConfig::validate() const {
  if (cores < 1 || cores > kMaxRtlCores)
    throw std::invalid_argument("core count must be 1 to " + std::to_string(kMaxRtlCores) +
                                ", got " + std::to_string(cores));
  golden.format.validate();
  if (golden.stackFrames < 1 || golden.stackFrames > kMaxStackFrames)
    throw std::invalid_argument("stack depth must be 1 to " + std::to_string(kMaxStackFrames) +
                                " frames, got " + std::to_string(golden.stackFrames));
}

namespace {

constexpr int kJobManagerStages = 6;  // P_STAGES

// job_t: what the job manager hands to the cores.
struct Job {
  size_t index = 0;  // in the host's job list: not an RTL signal, it names the job in the run
  uint32_t idWord = 0;
  uint8_t a = 0;
  uint32_t root = 0;
  std::array<int64_t, 3> t0{};
  std::array<int64_t, 3> t1{};
};

// The combinational signals of one cycle, named after the RTL's wires.
struct Wires {
  // host -> job_manager
  bool inValid = false;
  Job inRay;
  bool pipelineEnable = false;
  bool inReady = false;
  // job_manager -> scheduler -> cores
  bool schedValid = false;
  bool schedReady = false;
  Job pendingJob;
  std::vector<bool> coreInReady;
  std::vector<bool> coreInValid;
  // cores -> result_manager -> host
  std::vector<bool> coreOutValid;
  std::vector<bool> coreOutReady;
  std::vector<TraversalResult> coreOutResult;
  bool outValid = false;
  bool outReady = true;
  TraversalResult outResult;
};

struct JobManager {
  std::array<bool, kJobManagerStages> validDelay{};
  // The job fields and, in step with them, the t-values of the conversion pipeline.
  std::array<Job, kJobManagerStages> pipeline{};
};

struct Core {
  TraversalCore<FixedArith> traversal;  // core_state, the frames and the result fields
  uint32_t idWord = 0;                  // out_result.job_id
};

struct ResultManager {
  std::vector<bool> resultValid;
  std::vector<TraversalResult> resultBuffer;
  int resultSelect = 0;
};

// core_select and result_select: count 0 .. count - 1 and wrap, every cycle.
int nextSelect(int select, int count) { return select < count - 1 ? select + 1 : 0; }

class RtlTop {
 public:
  RtlTop(const SvoMemory& memory, const std::vector<TraversalJob>& jobs,
         const RtlTopConfig& config);

  RtlTopRun run();

 private:
  Job offeredJob() const;
  Wires evaluate() const;
  // Each clock function updates one module from the wires and its own registers only, so the
  // order in which they run does not matter.
  void clockHost(const Wires& wires);
  void clockJobManager(const Wires& wires);
  void clockScheduler();
  void clockCores(const Wires& wires);
  void clockResultManager(const Wires& wires);

  SvoMemory memory_;
  const std::vector<TraversalJob>& jobs_;
  RtlTopConfig config_;
  uint64_t cycle_ = 0;
  size_t nextJob_ = 0;
  JobManager jobManager_;
  int coreSelect_ = 0;
  std::vector<Core> cores_;
  ResultManager resultManager_;
  RtlTopRun run_;
};

RtlTop::RtlTop(const SvoMemory& memory, const std::vector<TraversalJob>& jobs,
               const RtlTopConfig& config)
    : memory_(memory), jobs_(jobs), config_(config) {
  config_.validate();
  const size_t cores = static_cast<size_t>(config_.cores);
  const Core idle{TraversalCore<FixedArith>(FixedArith{config_.golden.format},
                                            config_.golden.stackFrames)};
  cores_.assign(cores, idle);
  resultManager_.resultValid.assign(cores, false);
  resultManager_.resultBuffer.assign(cores, TraversalResult{});
  run_.acceptCycles.assign(jobs.size(), 0);
  run_.dispatchCycles.assign(jobs.size(), 0);
}

RtlTopRun RtlTop::run() {
  while (run_.results.size() < jobs_.size()) {
    const Wires wires = evaluate();
    clockHost(wires);
    clockJobManager(wires);
    clockScheduler();
    clockCores(wires);
    clockResultManager(wires);
    ++cycle_;
  }
  run_.totalCycles = cycle_;
  return run_;
}

// in_ray. The conversion is a pure function of the input, so converting on entry and carrying the
// result down the six stages gives what float_to_fixed delivers at the end of them.
Job RtlTop::offeredJob() const {
  const TraversalJob& job = jobs_[nextJob_];
  const GoldenConfig& golden = config_.golden;
  return Job{nextJob_,
             job.idWord(),
             job.a,
             job.root,
             convertToFixed(job.t0Bits, golden.format, golden.conversion),
             convertToFixed(job.t1Bits, golden.format, golden.conversion)};
}

Wires RtlTop::evaluate() const {
  const size_t cores = cores_.size();
  Wires w;
  w.coreInReady.assign(cores, false);
  w.coreInValid.assign(cores, false);
  w.coreOutValid.assign(cores, false);
  w.coreOutReady.assign(cores, false);
  w.coreOutResult.assign(cores, TraversalResult{});

  // svo_trav_core
  for (size_t i = 0; i < cores; ++i) {
    const CoreState state = cores_[i].traversal.state();
    w.coreInReady[i] = state == CoreState::Idle;
    w.coreOutValid[i] = state == CoreState::Out;
    if (w.coreOutValid[i]) w.coreOutResult[i] = makeResult(cores_[i].idWord, cores_[i].traversal);
  }

  // result_manager
  const ResultManager& rm = resultManager_;
  for (size_t i = 0; i < cores; ++i) w.coreOutReady[i] = !rm.resultValid[i];
  w.outValid = rm.resultValid[rm.resultSelect];
  w.outResult = rm.resultBuffer[rm.resultSelect];

  // scheduler
  w.schedReady = w.coreInReady[coreSelect_];
  w.schedValid = jobManager_.validDelay.back();
  for (size_t i = 0; i < cores; ++i)
    w.coreInValid[i] = w.schedValid && i == static_cast<size_t>(coreSelect_);

  // job_manager
  w.pendingJob = jobManager_.pipeline.back();
  w.pipelineEnable = w.schedReady || !w.schedValid;
  w.inReady = w.pipelineEnable;

  // host
  w.inValid = nextJob_ < jobs_.size();
  if (w.inValid) w.inRay = offeredJob();
  w.outReady = true;
  return w;
}

void RtlTop::clockHost(const Wires& w) {
  if (w.inValid && w.inReady) {
    run_.acceptCycles[nextJob_] = cycle_;
    ++nextJob_;
  }
  if (w.outValid && w.outReady) {
    run_.results.push_back(w.outResult);
    run_.resultCycles.push_back(cycle_);
  }
}

void RtlTop::clockJobManager(const Wires& w) {
  if (!w.pipelineEnable) return;
  JobManager& jm = jobManager_;
  for (int stage = kJobManagerStages - 1; stage > 0; --stage) {
    jm.validDelay[stage] = jm.validDelay[stage - 1];
    jm.pipeline[stage] = jm.pipeline[stage - 1];
  }
  jm.validDelay[0] = w.inValid && w.inReady;
  jm.pipeline[0] = w.inRay;
}

void RtlTop::clockScheduler() { coreSelect_ = nextSelect(coreSelect_, config_.cores); }

void RtlTop::clockCores(const Wires& w) {
  const auto read = [this](uint32_t address) { return memory_.read(address); };
  for (size_t i = 0; i < cores_.size(); ++i) {
    Core& core = cores_[i];
    switch (core.traversal.state()) {
      case CoreState::Idle:
        if (w.coreInReady[i] && w.coreInValid[i]) {
          const Job& job = w.pendingJob;
          core.idWord = job.idWord;
          core.traversal.start(job.t0, job.t1, job.a, job.root);
          run_.dispatchCycles[job.index] = cycle_;
        }
        break;
      case CoreState::Out:
        if (w.coreOutReady[i]) core.traversal.finish();
        break;
      default:
        core.traversal.step(read);
        break;
    }
  }
}

void RtlTop::clockResultManager(const Wires& w) {
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

}  // namespace

RtlTopRun runRtlTop(const SvoMemory& memory, const std::vector<TraversalJob>& jobs,
                    const RtlTopConfig& config) {
  return RtlTop(memory, jobs, config).run();
}

}  // namespace rtu
