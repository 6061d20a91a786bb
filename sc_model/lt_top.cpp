#include "lt_top.h"

#include <string>

#include <tlm_utils/tlm_quantumkeeper.h>

namespace rtu {

LtTop::LtTop(sc_core::sc_module_name name, const RtuConfig& config, SvoMemory memory,
             const std::vector<HostRecord>& records, const CacheContents* startCaches)
    : sc_core::sc_module(name), time_(CycleClock::atMegahertz(config.clockMhz)) {
  tlm_utils::tlm_quantumkeeper::set_global_quantum(time_.period() *
                                                   static_cast<double>(config.ltQuantum));
  dispatcher_ = std::make_unique<LtDispatcher>(
      "dispatcher", memory, records,
      LtDispatcherConfig{config.cores, config.scheduler, config.jobManager, config.hostInput},
      time_);
  collector_ = std::make_unique<LtResultCollector>("collector", config.cores, config.outputLink(),
                                                   records.size(), time_);
  const GoldenConfig golden = config.golden();
  for (int i = 0; i < config.cores; ++i) {
    cores_.push_back(std::make_unique<LtTraversalCore>(("core_" + std::to_string(i)).c_str(), i,
                                                       golden.format, golden.stackFrames, time_));
    cores_.back()->jobs(*dispatcher_);
    cores_.back()->results(*collector_);
  }
  if (config.memory.ideal) {
    rom_ = std::make_unique<LtRom>("rom", memory);
    for (auto& core : cores_) core->memory.bind(rom_->socket);
  } else {
    bindCachedMemory(config, memory, startCaches);
  }
}

void LtTop::bindCachedMemory(const RtuConfig& config, SvoMemory memory,
                             const CacheContents* start) {
  const CacheArray* l2Start = start && !start->l2.empty() ? &start->l2.front() : nullptr;
  l2_ = std::make_unique<LtL2Cache>("l2", config.memory, time_, l2Start);
  dram_ = std::make_unique<LtDram>("dram", config.memory.dram, time_);
  l2_->dram.bind(dram_->socket);
  for (size_t i = 0; i < cores_.size(); ++i) {
    const CacheArray* l1Start = start && i < start->l1.size() ? &start->l1[i] : nullptr;
    l1_.push_back(std::make_unique<LtL1Cache>(("l1_" + std::to_string(i)).c_str(),
                                              config.memory.l1, memory, time_, l1Start));
    cores_[i]->memory.bind(l1_.back()->socket);
    l1_.back()->next.bind(l2_->socket);
  }
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
