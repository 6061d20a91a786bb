#pragma once
// How a traversal core reads SVO words. A core's private level (ideal ROM or its L1) answers at
// once with the cycle the word is there, so the core can run ahead through cycles nobody else
// sees. A shared level (the L2 behind the L1s) must see requests in cycle order across cores: the
// core registers its request for its cycle and stops; the memory serves the requests of a cycle
// when simulated time reaches it (all of them are known by then: a core registers a request only
// while running cycles before it) and tells each core the cycle its word is there.

#include <cstdint>

#include <systemc>

#include "svo_memory.h"

namespace rtu {

struct MemoryReply {
  bool known;      // true: the word is there in `cycle`; false: ask the shared level in `cycle`
  uint64_t cycle;
};

class SharedReadListener {
 public:
  virtual ~SharedReadListener() = default;
  // The word of the core's shared request is there in `dataCycle`.
  virtual void sharedReplied(uint64_t dataCycle) = 0;
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
  // The shared request lookup() asked for, in `cycle` (ahead of simulated time); `reader` hears
  // the cycle the word is there once simulated time reaches `cycle`.
  virtual void requestShared(int core, uint32_t address, uint64_t cycle,
                             SharedReadListener& reader) = 0;
};

}  // namespace rtu
