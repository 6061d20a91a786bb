#pragma once
// The memory the traversal cores read (thesis 6.2.5 used a combinational ROM): either `ideal` (the
// word in the same cycle, the thesis configuration) or an L1 per core in front of a shared L2 and
// DRAM (memory_config.h; timing in l1_cache_timing.h and l2_cache_timing.h). The caches hold tags
// only: the words come from the scene's image, so the model holds nothing the scene does not use.
//
// L1 lookups happen in the core's own (run-ahead) cycle, since only that core touches its L1.
// Misses reach the shared L2 in the cycle they are made; requests of one cycle are arbitrated
// round-robin over the cores, starting after the core served last. Pending requests wait in a
// calendar by cycle: a tournament tree over the cores (a core has one request at most), so a
// request and its service cost log2 N steps each. The memory is an agent of the decision pump
// that decides last, when every other decision is made: it serves the earliest cycle's requests
// as soon as no core can still make one for that cycle (the lowest cycle every core has
// published, below), which is usually long before simulated time gets there, and tells their
// cores by a call. Only when a cycle's requests are not all known yet does it wait for simulated
// time to reach that cycle, by when they are (docs/cycle-semantics.md, "Run-ahead").
//
// A core that waits for its word asks again only after the word is there, so after its request's
// cycle. A core that offered a result from O is handed over in K >= O and dispatched in D > K
// with D >= F, F the scheduler's floor, and reads first in D + R, R its kind's first read after
// dispatch (2 for SVO: INIT in D + 1, EVAL reads in D + 2): so no earlier than O + 1 + R nor
// F + R (a core not yet used, no earlier than R). A dispatch not yet decided is
// at or after simulated time, so F is at least that.
//
// Cores that share triangle units (core.triangle.shared_by) ask their unit through the same
// calendar, with ideal memory too: a request of a cycle is arbitrated once every request of that
// cycle is known (triangle_unit_arbiter.h), a request not granted goes back into the calendar for
// its unit's next free cycle. A core has one request at most, of either kind, and its first test
// follows its first read, so the bounds above hold for both.

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <systemc>

#include "base/lowest_of.h"
#include "rtu/word_memory.h"
#include "sim/ca/core_memory_if.h"
#include "sim/ca/triangle_unit_arbiter.h"
#include "sim/kernel/cycle_clock.h"
#include "sim/kernel/module_process.h"
#include "sim/memory/cache_contents.h"
#include "sim/memory/l1_cache_timing.h"
#include "sim/memory/l2_cache_timing.h"
#include "sim/memory/memory_config.h"
#include "trace/cycle_trace.h"

namespace rtu {

class MemorySystem final : public sc_core::sc_module, public CoreMemoryIf, public Agent {
 public:
  // `start`: lines resident from cycle 0 (functional warming), or null for empty caches. `units`:
  // the cores' triangle units (shared or not).
  MemorySystem(sc_core::sc_module_name name, const CycleClock& clock, DecisionPump& pump,
               WordMemory backing, MemoryConfig config, int cores, uint64_t firstReadAfterDispatch,
               TriangleUnitArbiter units, CycleTrace* trace, const CacheContents* start = nullptr);

  // The scheduler whose dispatches bound the idle cores' next requests.
  void followDispatches(DispatchFloor& scheduler);

  const WordMemory& backingStore() const override { return backing_; }
  bool combinational() const override { return config_.ideal; }
  L1CacheTiming* privateCache(int core) override {
    return config_.ideal ? nullptr : cores_[static_cast<size_t>(core)].l1.get();
  }
  void tracePrivateLookup(int core, uint64_t cycle) override;
  void requestShared(int core, uint32_t address, uint64_t cycle,
                     SharedReadListener& reader) override;
  void coreOffering(int core, uint64_t outCycle) override;
  bool trianglesShared() const override { return units_.shared(); }
  void requestTriangleUnit(int core, uint64_t cycle, SharedReadListener& reader) override;
  // Serves the earliest cycle's requests while all are known, cycle after cycle.
  void decide() override;
  void heard(int port) override;

  CacheStats l1Statistics(int core) const { return cores_[static_cast<size_t>(core)].l1->stats(); }
  L2Stats l2Statistics() const { return l2_ ? l2_->stats() : L2Stats{}; }

 private:
  static constexpr uint64_t kNoBound = UINT64_MAX;

  struct CorePort {
    std::unique_ptr<L1CacheTiming> l1;
    uint32_t pendingAddress = 0;
    SharedReadListener* reader = nullptr;  // null unless a request waits in the calendar
    bool unit = false;                     // the request asks for the triangle unit
    int hitSignal = CycleTrace::kNoSignal, missSignal = CycleTrace::kNoSignal;
  };
  // A request in the calendar: its cycle above the core's number, so that the calendar's order
  // is by cycle, then core; kNoBound for a core without one.
  uint64_t requestKey(uint64_t cycle, int core) const {
    return cycle << coreBits_ | static_cast<uint64_t>(core);
  }
  uint64_t cycleOf(uint64_t key) const { return key >> coreBits_; }
  int coreOf(uint64_t key) const {
    return static_cast<int>(key & ((uint64_t{1} << coreBits_) - 1));
  }

  void end_of_elaboration() override;
  // Whether it serves requests: of the shared level (cached memory) or of shared triangle units.
  bool serves() const { return !config_.ideal || units_.shared(); }
  void enterCalendar(int core, uint64_t cycle, SharedReadListener& reader);
  // Out of line, so that requestShared() needs no stack frame for the message.
  [[noreturn, gnu::noinline, gnu::cold]] void failBehind(int core, uint64_t cycle) const;
  // Whether no core can still make a request for `cycle`.
  bool requestsKnownFor(uint64_t cycle) const;
  bool requestsWait() const { return calendar_.lowest() != kNoBound; }
  uint64_t earliestRequestCycle() const { return cycleOf(calendar_.lowest()); }
  uint64_t dispatchFloor() const;
  void serveCycle(uint64_t cycle);
  // Out of line, as most cycles have a single request and no trace: serveCycle() then needs no
  // stack frame for the list of cores or the statistics.
  [[gnu::noinline]] void serveArbitrated(int first, uint64_t cycle);
  // The unit requests of `cycle` (in unitRequests_): the granted cores go on, the others wait.
  [[gnu::noinline]] void serveUnits(uint64_t cycle);
  [[gnu::noinline]] void traceShared(uint64_t cycle);
  int takeEarliest();
  void serve(int core, uint64_t cycle);
  // The next cycle's round-robin starts after `core`.
  void servedLast(int core);

  const CycleClock& clock_;
  WordMemory backing_;
  MemoryConfig config_;
  std::vector<CorePort> cores_;
  std::unique_ptr<L2CacheTiming> l2_;
  int coreBits_ = 0;  // bits of the largest core number
  LowestOf calendar_;
  std::vector<int> served_;  // the cores whose requests are of the cycle being served
  TriangleUnitArbiter units_;
  std::vector<int> unitRequests_, unitsGranted_;  // of the cycle being served
  std::vector<std::pair<int, uint64_t>> unitsDeferred_;
  int nextPriority_ = 0;
  uint64_t servedThrough_ = 0;  // the last cycle served (0 also before the first)
  uint64_t firstRead_;          // the cores' kind's first read after dispatch (rtu/core_kind.h)
  // Per core, the earliest cycle it can ask in, nor before the scheduler's floor + R: a core
  // offering (or handed over and not dispatched yet); kNoBound for a core whose request waits
  // (it asks again after its cycle) or that runs.
  LowestOf published_;
  DispatchFloor* dispatches_ = nullptr;
  CycleWake wake_;
  CycleTrace* trace_;
  int l2HitSignal_ = CycleTrace::kNoSignal, l2MissSignal_ = CycleTrace::kNoSignal;
};

}  // namespace rtu
