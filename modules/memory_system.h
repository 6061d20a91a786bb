#pragma once
// The memory the traversal cores read (thesis 6.2.5 used a combinational ROM): either `ideal` (the
// word in the same cycle, the thesis configuration) or an L1 per core in front of a shared L2 and
// DRAM (memory_config.h; timing in l1_cache_timing.h and l2_cache_timing.h). The caches hold tags
// only: the words come from the scene's image, so the model holds nothing the scene does not use.
//
// L1 lookups happen in the core's own (run-ahead) cycle, since only that core touches its L1.
// Misses reach the shared L2 in the cycle they are made; requests of one cycle are arbitrated
// round-robin over the cores, starting after the core served last. Pending requests wait in a
// calendar by cycle; one wake-up at its earliest cycle serves all requests of that cycle and
// tells their cores by a call (no kernel event per miss).

#include <cstdint>
#include <functional>
#include <memory>
#include <queue>
#include <vector>

#include <systemc>

#include "cache_contents.h"
#include "core_memory_if.h"
#include "cycle_clock.h"
#include "cycle_trace.h"
#include "l1_cache_timing.h"
#include "l2_cache_timing.h"
#include "memory_config.h"
#include "module_process.h"
#include "svo_memory.h"

namespace rtu {

class MemorySystem : public sc_core::sc_module, public CoreMemoryIf {
 public:
  // `start`: lines resident from cycle 0 (functional warming), or null for empty caches.
  MemorySystem(sc_core::sc_module_name name, const CycleClock& clock, SvoMemory backing,
               MemoryConfig config, int cores, CycleTrace* trace,
               const CacheContents* start = nullptr);

  const SvoMemory& backingStore() const override { return backing_; }
  bool combinational() const override { return config_.ideal; }
  MemoryReply lookup(int core, uint32_t address, uint64_t cycle) override;
  void requestShared(int core, uint32_t address, uint64_t cycle,
                     SharedReadListener& reader) override;

  CacheStats l1Statistics(int core) const { return cores_[static_cast<size_t>(core)].l1->stats(); }
  L2Stats l2Statistics() const { return l2_ ? l2_->stats() : L2Stats{}; }

 private:
  struct CorePort {
    std::unique_ptr<L1CacheTiming> l1;
    uint32_t pendingAddress = 0;
    SharedReadListener* reader = nullptr;
    int hitSignal = CycleTrace::kNoSignal, missSignal = CycleTrace::kNoSignal;
  };
  struct Request {
    uint64_t cycle;
    int core;
    bool operator>(const Request& other) const { return cycle > other.cycle; }
  };

  void end_of_elaboration() override;
  // Serves the requests of the current cycle, then waits for the next cycle with one.
  void serveShared();

  const CycleClock& clock_;
  SvoMemory backing_;
  MemoryConfig config_;
  std::vector<CorePort> cores_;
  std::unique_ptr<L2CacheTiming> l2_;
  std::priority_queue<Request, std::vector<Request>, std::greater<Request>> calendar_;
  std::vector<int> served_;  // the cores whose requests are of the cycle being served
  int nextPriority_ = 0;
  CycleWake wake_;
  CycleTrace* trace_;
  int l2HitSignal_ = CycleTrace::kNoSignal, l2MissSignal_ = CycleTrace::kNoSignal;
};

}  // namespace rtu
