#pragma once
// The loosely-timed model's transactions between the cores and the rest of the RTU: blocking
// interface calls whose cycles are annotated, as TLM-2.0's b_transport annotates its delay. A core
// asks for its next job when it is idle and hands its result over when it reaches OUT; both calls
// return at once with the cycles the cycle-accurate model's handshakes would have (estimated:
// docs/fidelity.md says how).

#include <cstdint>

#include <systemc>

#include "rtu_payloads.h"

namespace rtu {

struct LtDispatch {
  CoreJob job;
  uint64_t cycle = 0;  // the scheduler's handshake with the core: INIT follows in cycle + 1
};

class LtJobSourceIf : public virtual sc_core::sc_interface {
 public:
  // The next job for `core`, idle from cycle `idleFrom`; false when there is none left.
  virtual bool take(int core, uint64_t idleFrom, LtDispatch& dispatch) = 0;
};

class LtResultSinkIf : public virtual sc_core::sc_interface {
 public:
  // `core` offers `result` from cycle `outCycle` (OUT); returns the cycle it is idle from.
  virtual uint64_t handOver(int core, uint64_t outCycle, const CoreResult& result) = 0;
};

}  // namespace rtu
