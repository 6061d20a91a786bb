#include "lt_top.h"

#include <string>

#include "job_manager.h"

namespace rtu {

LtTop::LtTop(sc_core::sc_module_name name, const RtuConfig& config, SvoMemory memory,
             const std::vector<HostRecord>& records)
    : sc_core::sc_module(name),
      config_(config),
      records_(records),
      time_(CycleClock::atMegahertz(config.clockMhz)),
      setup_(memory, config.jobManager) {
  tlm_utils::tlm_quantumkeeper::set_global_quantum(time_.period() *
                                                   static_cast<double>(config.ltQuantum));
  const GoldenConfig golden = config.golden();
  for (int i = 0; i < config.cores; ++i)
    cores_.push_back(std::make_unique<LtTraversalCore>(("core_" + std::to_string(i)).c_str(),
                                                       golden.format, golden.stackFrames, time_));
  if (config.memory.ideal) {
    rom_ = std::make_unique<LtRom>("rom", memory);
    for (auto& core : cores_) core->memory.bind(rom_->socket);
  } else {
    bindCachedMemory(config, memory);
  }
  SC_HAS_PROCESS(LtTop);
  SC_THREAD(drive);
}

void LtTop::bindCachedMemory(const RtuConfig& config, SvoMemory memory) {
  l2_ = std::make_unique<LtL2Cache>("l2", config.memory, time_);
  dram_ = std::make_unique<LtDram>("dram", config.memory.dram, time_);
  l2_->dram.bind(dram_->socket);
  for (size_t i = 0; i < cores_.size(); ++i) {
    l1_.push_back(std::make_unique<LtL1Cache>(("l1_" + std::to_string(i)).c_str(),
                                              config.memory.l1, memory, time_));
    cores_[i]->memory.bind(l1_.back()->socket);
    l1_.back()->next.bind(l2_->socket);
  }
}

// The job manager's set-up of every record (in host order: model headers are read by the first
// ray against them), then the recurrence, which calls traverse() at each dispatch.
void LtTop::drive() {
  std::vector<RecurrenceJob> pipeline;
  pipeline.reserve(records_.size());
  jobs_.reserve(records_.size());
  for (size_t i = 0; i < records_.size(); ++i) {
    const JobSetup::SetUp set = setup_.setUp(records_[i]);
    pipeline.push_back(RecurrenceJob{0, set.latency, set.headerFetch});
    jobs_.push_back(set.job);
  }
  results_.resize(records_.size());
  blocked_.resize(records_.size());
  quantum_.reset();
  timing_ = runRecurrence(
      pipeline, RecurrenceConfig{config_.cores, config_.scheduler, config_.hostInput, config_.outputLink()},
      [this](size_t job, int core, uint64_t initCycle) { return traverse(job, core, initCycle); });
}

// Dispatches come in cycle order: the thread's local time is the latest, synchronised with the
// kernel once it runs a quantum ahead.
uint64_t LtTop::traverse(size_t job, int core, uint64_t initCycle) {
  quantum_.set(time_.delayTo(initCycle));
  if (quantum_.need_sync()) quantum_.sync();
  const CoreJob fixed = coreJobOf(PayloadIds::plain(job), jobs_[job], config_.jobManager);
  const CoreResult result = cores_[static_cast<size_t>(core)]->traverse(fixed, initCycle);
  results_[job] = result.result;
  blocked_[job] = result.blockedCycles;
  return result.result.cost + result.blockedCycles;
}

std::vector<CacheStats> LtTop::l1Statistics() const {
  std::vector<CacheStats> stats;
  for (const auto& l1 : l1_) stats.push_back(l1->statistics());
  return stats;
}

L2Stats LtTop::l2Statistics() const {
  if (!l2_) return {};
  L2Stats stats = l2_->statistics();
  stats.dram = dram_->statistics();
  return stats;
}

}  // namespace rtu
