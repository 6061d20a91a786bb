#include "memory_system.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace rtu {

MemorySystem::MemorySystem(sc_core::sc_module_name name, const CycleClock& clock,
                           SvoMemory backing, MemoryConfig config, int cores, CycleTrace* trace,
                           const CacheContents* start)
    : sc_core::sc_module(name),
      clock_(clock),
      backing_(backing),
      config_(config),
      cores_(static_cast<size_t>(cores)),
      wake_(clock),
      trace_(trace) {
  if (config_.ideal) return;
  validate(config_);
  l2_ = std::make_unique<L2CacheTiming>(config_.l2, config_.dram);
  if (start && !start->l2.empty()) l2_->startFrom(start->l2.front());
  for (size_t i = 0; i < cores_.size(); ++i) {
    CorePort& port = cores_[i];
    port.l1 = std::make_unique<L1CacheTiming>(config_.l1);
    if (start && i < start->l1.size()) port.l1->startFrom(start->l1[i]);
    if (trace_) {
      const std::string scope = std::string(this->name()) + ".l1_" + std::to_string(i);
      port.hitSignal = trace_->declare(scope, "hits", 32);
      port.missSignal = trace_->declare(scope, "misses", 32);
    }
  }
  if (trace_) {
    const std::string scope = std::string(this->name()) + ".l2";
    l2HitSignal_ = trace_->declare(scope, "hits", 32);
    l2MissSignal_ = trace_->declare(scope, "misses", 32);
  }
}

void MemorySystem::end_of_elaboration() {
  if (!config_.ideal) spawnReaction("serve_shared", [this] { serveShared(); }, {&wake_.event()});
}

MemoryReply MemorySystem::lookup(int core, uint32_t address, uint64_t cycle) {
  if (config_.ideal) return {true, cycle};
  CorePort& port = cores_[static_cast<size_t>(core)];
  const L1Lookup result = port.l1->lookup(address, cycle);
  if (trace_) {
    trace_->record(port.hitSignal, cycle, port.l1->stats().hits + port.l1->stats().merged);
    trace_->record(port.missSignal, cycle, port.l1->stats().misses);
  }
  return {result.hit, result.cycle};
}

void MemorySystem::requestShared(int core, uint32_t address, uint64_t cycle,
                                 SharedReadListener& reader) {
  if (cycle <= clock_.now())
    throw std::logic_error("shared memory request of core " + std::to_string(core) +
                           " for cycle " + std::to_string(cycle) + ", not after simulated time");
  CorePort& port = cores_[static_cast<size_t>(core)];
  port.pendingAddress = address;
  port.reader = &reader;
  calendar_.push({cycle, core});
  if (calendar_.top().cycle == cycle) wake_.at(cycle);
}

void MemorySystem::serveShared() {
  const uint64_t now = clock_.now();
  served_.clear();
  while (!calendar_.empty() && calendar_.top().cycle == now) {
    served_.push_back(calendar_.top().core);
    calendar_.pop();
  }
  // Round-robin: from the core after the one served last on (a core has one request at most).
  std::sort(served_.begin(), served_.end());
  std::rotate(served_.begin(), std::lower_bound(served_.begin(), served_.end(), nextPriority_),
              served_.end());
  for (int core : served_) {
    CorePort& port = cores_[static_cast<size_t>(core)];
    const uint64_t line = L1CacheTiming::byteAddress(port.pendingAddress);
    // The core goes on at once and may register its next request (for a later cycle).
    port.reader->sharedReplied(port.l1->fill(port.pendingAddress, l2_->read(line, now)));
  }
  if (!served_.empty()) nextPriority_ = (served_.back() + 1) % static_cast<int>(cores_.size());
  if (!calendar_.empty()) wake_.at(calendar_.top().cycle);
  if (trace_ && !served_.empty()) {
    const L2Stats stats = l2_->stats();
    trace_->record(l2HitSignal_, now, stats.cache.hits + stats.cache.merged);
    trace_->record(l2MissSignal_, now, stats.cache.misses);
  }
}

}  // namespace rtu
