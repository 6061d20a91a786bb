#pragma once
// How a traversal core reads SVO words. A core's private level (ideal ROM or its L1) answers at
// once with the cycle the word is there, so the core can run ahead through cycles nobody else
// sees. A shared level (the L2 behind the L1s) must see requests in cycle order across cores, so
// the core waits until the request cycle and asks then.

#include <cstdint>

#include <systemc>

#include "svo_memory.h"

namespace rtu {

struct MemoryReply {
  bool known;      // true: the word is there in `cycle`; false: ask the shared level in `cycle`
  uint64_t cycle;
};

class CoreMemoryIf : public virtual sc_core::sc_interface {
 public:
  // The words themselves (timing is the other calls' business).
  virtual const SvoMemory& backingStore() const = 0;
  // True for the thesis' combinational ROM: every word is there in the cycle it is read, so a
  // core need not ask lookup().
  virtual bool combinational() const = 0;
  // A read the core issues in `cycle` (its own, possibly ahead of simulated time).
  virtual MemoryReply lookup(int core, uint32_t address, uint64_t cycle) = 0;
  // The shared request lookup() asked for, made in the current cycle; `sharedReplied(core)` is
  // notified once `sharedReplyCycle(core)`, the cycle the word is there, is known.
  virtual void requestShared(int core, uint32_t address) = 0;
  virtual uint64_t sharedReplyCycle(int core) const = 0;
  virtual const sc_core::sc_event& sharedReplied(int core) const = 0;
};

}  // namespace rtu
