#include "memory_system.h"

#include <algorithm>
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
      trace_(trace) {
  for (CorePort& port : cores_) port.replied = std::make_unique<sc_core::sc_event>();
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
  SC_HAS_PROCESS(MemorySystem);
  SC_METHOD(serveShared);
  sensitive << requested_;
  dont_initialize();
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

void MemorySystem::requestShared(int core, uint32_t address) {
  cores_[static_cast<size_t>(core)].pendingAddress = address;
  queue_.push_back(core);
  requested_.notify(sc_core::SC_ZERO_TIME);
}

void MemorySystem::serveShared() {
  const uint64_t now = clock_.now();
  const int n = static_cast<int>(cores_.size());
  const auto priority = [&](int core) { return (core - nextPriority_ + n) % n; };
  std::sort(queue_.begin(), queue_.end(), [&](int a, int b) { return priority(a) < priority(b); });
  for (int core : queue_) {
    CorePort& port = cores_[static_cast<size_t>(core)];
    const uint64_t line = L1CacheTiming::byteAddress(port.pendingAddress);
    port.replyCycle = port.l1->fill(port.pendingAddress, l2_->read(line, now));
    port.replied->notify(sc_core::SC_ZERO_TIME);
  }
  nextPriority_ = (queue_.back() + 1) % n;
  queue_.clear();
  if (trace_) {
    const L2Stats stats = l2_->stats();
    trace_->record(l2HitSignal_, now, stats.cache.hits + stats.cache.merged);
    trace_->record(l2MissSignal_, now, stats.cache.misses);
  }
}

}  // namespace rtu
