#pragma once
// How a traversal core reads its words (and asks for a shared triangle unit, which is arbitrated
// by the same cycle-ordered rule as the shared level). A core's private level (ideal ROM or its L1)
// answers at once with the cycle the word is there, so the core can run ahead through cycles nobody
// else sees. A shared level (the L2 behind the L1s) must see requests in cycle order across cores:
// the core registers its request for its cycle and stops; the memory serves the requests of a cycle
// once no core can still make one for it, and tells each core the cycle its word is there. To
// know that, the memory hears from each core the earliest cycle it can ask again (coreOffering; a
// core waiting for its word asks again only after it) and from the scheduler the earliest cycle
// it can still dispatch a job (DispatchFloor).

#include <cstdint>

#include <systemc>

#include "rtu/word_memory.h"
#include "sim/kernel/decision_pump.h"
#include "sim/memory/l1_cache_timing.h"

namespace rtu {

// The scheduler as the memory sees it: the earliest cycle it can still dispatch a job in. A
// value the scheduler raises rather than a virtual call, as the memory reads it for every cycle
// it serves.
class DispatchFloor {
 public:
  // No job is dispatched before this cycle any more; it only rises.
  uint64_t noDispatchBefore() const { return floor_; }
  // `watcher` hears (Agent::heard) when noDispatchBefore() rises.
  void watchDispatchFloor(Agent& watcher) { watcher_ = &watcher; }

 protected:
  void raiseDispatchFloor(uint64_t cycle) {
    if (cycle == floor_) return;
    floor_ = cycle;
    if (watcher_) watcher_->heard(0);
  }

 private:
  uint64_t floor_ = 0;
  Agent* watcher_ = nullptr;
};

// A core waiting for a shared resource: the shared memory level, or its group's triangle unit.
class SharedReadListener {
 public:
  virtual ~SharedReadListener() = default;
  // The word of the core's shared request is there in `dataCycle`.
  virtual void sharedReplied(uint64_t dataCycle) = 0;
  // The core's shared triangle unit took its test in `cycle` (triangle_unit_arbiter.h).
  virtual void unitGranted(uint64_t cycle) = 0;
  // Its unit did not take the test in the cycle asked, but may in `cycle`: the core raises the
  // bounds it declared on its channels, as the grant's cycle is not known before then.
  virtual void unitDeferred(uint64_t cycle) = 0;
};

class CoreMemoryIf : public virtual sc_core::sc_interface {
 public:
  // The words themselves (timing is the other calls' business).
  virtual const WordMemory& backingStore() const = 0;
  // True for the thesis' combinational ROM: every word is there in the cycle it is read, so a
  // core need not look it up.
  virtual bool combinational() const = 0;
  // The core's L1 (null for the ROM). The core looks its reads up there itself, in its own
  // (run-ahead) cycle, since no other core touches it; a miss goes to requestShared.
  virtual L1CacheTiming* privateCache(int core) = 0;
  // For the trace: the core looked a read up in its L1 in `cycle`.
  virtual void tracePrivateLookup(int core, uint64_t cycle) = 0;
  // The shared request of an L1 miss, in `cycle` (ahead of simulated time); `reader` hears
  // the cycle the word is there once every request of `cycle` is known.
  virtual void requestShared(int core, uint32_t address, uint64_t cycle,
                             SharedReadListener& reader) = 0;
  // The core offers its result from `outCycle`. Called by a core that reads the shared level or
  // shares a triangle unit.
  virtual void coreOffering(int core, uint64_t outCycle) = 0;
  // Whether the cores share triangle units (core.triangle.shared_by > 1 with a kind that has one).
  virtual bool trianglesShared() const = 0;
  // The core's state of `cycle` issues a test to its shared triangle unit (ahead of simulated
  // time); `reader` hears the cycle the unit takes it, once every request of that cycle is known.
  virtual void requestTriangleUnit(int core, uint64_t cycle, SharedReadListener& reader) = 0;
};

}  // namespace rtu
