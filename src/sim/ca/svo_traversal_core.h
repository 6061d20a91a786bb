#pragma once
// The SVO traversal core (thesis 6.2.3, appendix C.4) with the BLOCKED state the thesis proposes
// for memory that does not answer in the same cycle. The state machine is src/kinds/svo/traversal_core.h,
// shared with the golden model; this module only decides when each state happens.
//
// Nothing outside the core can observe it between taking a job and offering the result, except
// its reads of a shared memory level. So when a job is delivered for cycle D the core steps the
// state machine from INIT in D + 1 through as many cycles as it can at once (all of them with
// ideal memory) and offers the result from the cycle OUT begins; it records each state in its own
// cycle for the trace. A read that must go to the shared level is registered with the memory for
// its cycle and the core stops, since the shared level serves requests in cycle order once every
// request of their cycle is known (core_memory_if.h); meanwhile the core declares that it offers
// no result and is not ready before then. The memory's reply lets it go on. The core tells the
// memory when it offers its result, which bounds its next request.
//
// A read issued in cycle c whose word is there in cycle d > c costs EVAL (or PUSH) in c and
// BLOCKED in c+1..d; the state consumes the word in d and the next state starts in d+1. The cost
// in the result counts every cycle from INIT to the last before OUT, blocked ones included.
// The core is ready for a job from cycle 0 and from the cycle after its result was taken.

#include <cstdint>
#include <string>
#include <vector>

#include <systemc>

#include "sim/ca/core_memory_if.h"
#include "trace/cycle_trace.h"
#include "sim/kernel/decision_pump.h"
#include "sim/ca/rtu_payloads.h"
#include "sim/kernel/transfer_channel.h"
#include "kinds/svo/state_vocabulary.h"
#include "kinds/svo/traversal_core.h"
#include "rtu/core_statistics.h"

namespace rtu {

class SvoTraversalCore final : public sc_core::sc_module, public Agent, private SharedReadListener {
 public:
  sc_core::sc_port<CoreMemoryIf> memory;

  SvoTraversalCore(sc_core::sc_module_name name, DecisionPump& pump,
                   int index, FixedFormat format, int stackFrames, CycleTrace* trace);

  void bind(TransferChannel<CoreJob>& in, TransferChannel<CoreResult>& out);
  void decide() override;

  const CoreStatistics& statistics() const { return statistics_; }

 private:
  // Idle: ready for a job. AwaitingShared: a read waits for the shared memory level.
  // Out: result offered.
  enum class Phase { Idle, AwaitingShared, Out };

  void end_of_elaboration() override;
  void sharedReplied(uint64_t dataCycle) override;
  void start(uint64_t dispatch, const CoreJob& job);
  void run(bool wordThere = false);
  template <bool kTraced>
  void steps(bool wordThere);
  // Forced inline: it runs once per simulated state, and a call costs a fifth of a state.
  template <bool kTraced>
  [[gnu::always_inline]] inline void stepState();
  // An L1 lookup's answer, small enough to come back in registers.
  struct PrivateRead {
    bool hit;
    uint64_t cycle;  // hit: the word is there; miss: the shared request's cycle
  };
  // Out of line: inlined, the lookup makes the stepping loop slower.
  template <bool kTraced>
  [[gnu::noinline]] PrivateRead lookUp(uint32_t address);
  template <bool kTraced>
  void consumeWordIn(uint64_t dataCycle);
  void waitForWord(uint64_t dataCycle);
  void offerResult();
  void handOver();
  void traceState(uint64_t cycle, uint64_t code);

  int index_;
  TraversalCore<FixedArith> core_;
  TransferChannel<CoreJob>* in_ = nullptr;
  TransferChannel<CoreResult>* out_ = nullptr;
  Phase phase_ = Phase::Idle;
  PayloadIds ids_;  // of the current job, for its result
  uint32_t idWord_ = 0;
  uint64_t localCycle_ = 0;  // the cycle the core's current state executes in
  uint64_t outCycle_ = 0;
  uint64_t blocked_ = 0;     // blocked cycles of the current job
  const SvoMemory* words_ = nullptr;
  bool combinational_ = false;
  L1CacheTiming* l1_ = nullptr;  // null for the combinational ROM
  CycleTrace* trace_;
  int stateSignal_ = CycleTrace::kNoSignal, stackSignal_ = CycleTrace::kNoSignal;
  CoreStatistics statistics_;
};

}  // namespace rtu
