#include "sim/lt/lt_top.h"

#include <stdexcept>
#include <string>

#include "base/prefault.h"

namespace rtu {

LtTop::LtTop(sc_core::sc_module_name name, const RtuConfig& config, WordMemory memory,
             const std::vector<HostRecord>& records)
    : sc_core::sc_module(name),
      config_(config),
      records_(records),
      time_(CycleClock::atMegahertz(config.clockMhz)),
      setup_(memory, config.jobManager),
      stateMachine_(FixedArith{config.golden().format}, config.golden().stackFrames) {
  tlm_utils::tlm_quantumkeeper::set_global_quantum(time_.period() *
                                                   static_cast<double>(config.ltQuantum));
  for (int i = 0; i < config.cores; ++i)
    cores_.push_back(std::make_unique<LtTraversalCore>(("core_" + std::to_string(i)).c_str(),
                                                       stateMachine_, time_));
  if (config.memory.ideal) {
    rom_ = std::make_unique<LtRom>("rom", memory);
    for (auto& core : cores_) core->memory.bind(rom_->socket);
  } else {
    bindCachedMemory(config, memory);
  }
  SC_HAS_PROCESS(LtTop);
  SC_THREAD(drive);
}

void LtTop::bindCachedMemory(const RtuConfig& config, WordMemory memory) {
  l2_ = std::make_unique<LtL2Cache>("l2", config.memory, time_);
  dram_ = std::make_unique<LtDram>("dram", config.memory.dram, time_);
  l2_->dram.bind(dram_->socket);
  for (size_t i = 0; i < cores_.size(); ++i) {
    l1_.push_back(std::make_unique<LtL1Cache>(("l1_" + std::to_string(i)).c_str(), config.memory.l1,
                                              memory, time_));
    cores_[i]->memory.bind(l1_.back()->socket);
    l1_.back()->next.bind(l2_->socket);
  }
}

// The recurrence asks for each record in host order: the job manager sets it up then (model
// headers are read by the first ray against them), and the recurrence calls traverse() at its
// dispatch, before it asks for the next.
void LtTop::drive() {
  results_.reserve(records_.size());
  blocked_.reserve(records_.size());
  prefaultCapacity(results_);  // a frame's results are tens of MB: mapped at once
  prefaultCapacity(blocked_);
  quantum_.reset();
  timing_ = runRecurrence(
      records_.size(), [this](size_t job) { return setUp(job); },
      RecurrenceConfig{config_.cores, config_.scheduler, config_.hostInput, config_.outputLink()},
      [this](size_t job, int core, uint64_t initCycle) { return traverse(job, core, initCycle); });
}

RecurrenceJob LtTop::setUp(size_t job) {
  const JobSetUp<SvoJob> set = setup_.setUp(records_[job]);
  current_ = CoreJob{PayloadIds::plain(job), set.idWord, set.job};
  return RecurrenceJob{0, set.latency, set.headerFetch};
}

// Dispatches come in cycle order: the thread's local time is the latest, synchronised with the
// kernel once it runs a quantum ahead. They come in job order too, each right after its set-up.
uint64_t LtTop::traverse(size_t job, int core, uint64_t initCycle) {
  if (job != results_.size()) throw std::logic_error("LtTop: jobs must be dispatched in order");
  quantum_.set(time_.delayTo(initCycle));
  if (quantum_.need_sync()) quantum_.sync();
  TraversalResult& result = results_.emplace_back();
  const uint32_t blocked = cores_[static_cast<size_t>(core)]->traverse(current_, initCycle, result);
  blocked_.push_back(blocked);
  return result.cost + blocked;
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
