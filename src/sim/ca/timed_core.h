#pragma once
// A traversal core of the cycle-accurate RTU (thesis 6.2.3, appendix C.4), for any core kind
// (rtu/core_kind.h), with the BLOCKED state the thesis proposes for memory that does not answer in
// the same cycle. The state machine is the kind's behaviour, shared with the golden model; this
// module only decides when each state happens.
//
// Nothing outside the core can observe it between taking a job and offering the result, except
// its reads of a shared memory level. So when a job is delivered for cycle D the core steps the
// state machine from its first state in D + 1 through as many cycles as it can at once (all of
// them with ideal memory) and offers the result from the cycle OUT begins; it records each state
// in its own cycle for the trace. A read that must go to the shared level is registered with the
// memory for its cycle and the core stops, since the shared level serves requests in cycle order
// once every request of their cycle is known (core_memory_if.h); meanwhile the core declares that
// it offers no result and is not ready before then. The memory's reply lets it go on. The core
// tells the memory when it offers its result, which bounds its next request.
//
// A state takes Kind::stateCycles cycles (one for SVO), c .. c+k-1, and issues its read, of
// Kind::kWordsPerRead words within one line, in c. Its word there in cycle d > c+k-1 costs
// BLOCKED in c+k..d; the state consumes the word in d and the next state starts in d+1
// (docs/cycle-semantics.md, "Access width and multi-cycle states"). The cost in the result
// counts every cycle from the first state to the last before OUT, blocked ones included. The core
// is ready for a job from cycle 0 and from the cycle after its result was taken.
//
// With a shared triangle unit (core.triangle.shared_by), a state that issues a test asks the unit
// in its first cycle s through the memory system, which arbitrates the cycle's requests once all
// are known (triangle_unit_arbiter.h), and stops like a shared read; granted in g >= s, the state
// takes its cycles from g (g - s stall cycles, counted apart from its cost; the trace shows the
// state from s).

#include <algorithm>
#include <cstdint>
#include <memory>
#include <variant>

#include <systemc>

#include "kinds/core_result.h"
#include "kinds/core_statistics.h"
#include "sim/ca/core_memory_if.h"
#include "sim/ca/rtu_payloads.h"
#include "sim/kernel/decision_pump.h"
#include "sim/kernel/transfer_channel.h"
#include "sim/rtu_config.h"
#include "trace/cycle_trace.h"

namespace rtu {

// What the RTU's top needs of a core of any kind: its channels once, its statistics at the end.
class TimedCoreBase : public sc_core::sc_module, public Agent {
 public:
  sc_core::sc_port<CoreMemoryIf> memory;
  static constexpr int kJobsPort = 0, kResultsPort = 1;  // its ports on the transfer channels

  TimedCoreBase(sc_core::sc_module_name name, DecisionPump& pump) : sc_module(name), Agent(pump) {}
  virtual void bind(TransferChannel<CoreJob>& in, TransferChannel<CoreResult>& out) = 0;
  const CoreStatistics& statistics() const { return statistics_; }

 protected:
  CoreStatistics statistics_;
};

// A core of the kind `config.core` chosen once for the RTU (kinds/registry.h). Defined in
// timed_core.cpp, which instantiates TimedCore for every kind in a translation unit of its own:
// the stepping loop's inlining depends on it (in the RTU top's unit the state machine's step
// stayed a call, 18 % more instructions per frame).
std::unique_ptr<TimedCoreBase> makeTimedCore(const RtuConfig& config, const char* name,
                                             DecisionPump& pump, int index, CycleTrace* trace);

template <class Kind>
class TimedCore final : public TimedCoreBase, private SharedReadListener {
 public:
  TimedCore(sc_core::sc_module_name name, DecisionPump& pump, int index,
            const typename Kind::Config& config, CycleTrace* trace)
      : TimedCoreBase(name, pump), index_(index), core_(Kind::behaviour(config)), trace_(trace) {
    if (trace_) {
      const StateVocabulary states = Kind::vocabulary();
      stateSignal_ = trace_->declare(this->name(), "state", states.bits, states.names);
      stackSignal_ = trace_->declare(this->name(), "stack_depth", 7);
    }
  }

  void bind(TransferChannel<CoreJob>& in, TransferChannel<CoreResult>& out) override {
    in_ = &in;
    out_ = &out;
    traceState(0, Kind::kIdleState);
    in_->readyFrom(0);
  }

  void decide() override {
    in_->collectDelivered([this](uint64_t cycle, const CoreJob& job) {
      start(cycle, job);
      run();
    });
    if (phase_ != Phase::Out) return;
    if (out_->collectTaken())
      handOver();
    else if (out_->readyBound() > outCycle_ && in_->readyBound() < out_->readyBound() + 1)
      in_->notReadyBefore(out_->readyBound() +
                          1);  // the result manager takes it then at the earliest
  }

 private:
  // Idle: ready for a job. AwaitingShared: a read waits for the shared memory level.
  // Out: result offered.
  enum class Phase { Idle, AwaitingShared, Out };
  // An L1 lookup's answer, small enough to come back in registers.
  struct PrivateRead {
    bool hit;
    uint64_t cycle;  // hit: the word is there; miss: the shared request's cycle
  };

  void end_of_elaboration() override {
    words_ = &memory->backingStore();
    combinational_ = memory->combinational();
    unitShared_ = HasTriangleUnit<Kind>::value && memory->trianglesShared();
    l1_ = memory->privateCache(index_);
  }

  // The shared level served the request: the word is there in `dataCycle`. (Called while the
  // pump runs: what the core decides puts others on it.)
  void sharedReplied(uint64_t dataCycle) override {
    waitForWord(dataCycle);
    run(true);
  }
  // The shared triangle unit took the test of the state waiting since localCycle_ in `cycle`: the
  // state's cycles run from there.
  void unitGranted(uint64_t cycle) override {
    statistics_.unitStallCycles += cycle - localCycle_;
    localCycle_ = cycle;
    run(true);
  }
  // Not granted before `cycle`: the state ends no earlier than its cycles from there.
  void unitDeferred(uint64_t cycle) override {
    declareStateEnd(cycle + Kind::stateCycles(core_) - 1);
  }

  void start(uint64_t dispatch, const CoreJob& job) {
    ids_ = job.ids;
    idWord_ = job.idWord;
    // The job manager set the job up for this kind: no check (std::get would test and throw).
    Kind::start(core_, *std::get_if<typename Kind::Job>(&job.job));
    localCycle_ = dispatch + 1;
    blocked_ = 0;
    ++statistics_.jobs;
  }

  // Steps the state machine (first the current state, if its word is there) until OUT or until a
  // read needs the shared level. The loop is compiled with and without the trace's records, so
  // that an untraced run does not test for the trace in every state.
  void run(bool wordThere = false) {
    if (trace_)
      steps<true>(wordThere);
    else
      steps<false>(wordThere);
  }

  template <bool kTraced>
  void steps(bool wordThere) {
    if (wordThere) stepState<kTraced>();
    while (core_.busy()) {
      if (kTraced) traceState(localCycle_, static_cast<uint64_t>(core_.state()));
      // A kind without a triangle unit (SVO) has no test here at all.
      if constexpr (HasTriangleUnit<Kind>::value) {
        if (unitShared_ && issuesTriangleTest<Kind>(core_)) {
          awaitUnit();
          return;
        }
      }
      if (!combinational_ && core_.readsMemory()) {
        const uint32_t address = core_.memoryAddress();
        const PrivateRead reply = lookUp<kTraced>(address);
        if (!reply.hit) {
          // BLOCKED until the shared level answers. Recorded now, as a trace takes no record
          // behind simulated time and the core resumes only in reply.cycle. (Should the word come
          // in this very cycle, the next state's record in the same cycle replaces it.)
          traceState(lastStateCycle() + 1, Kind::kBlockedState);
          phase_ = Phase::AwaitingShared;
          memory->requestShared(index_, address, reply.cycle, *this);
          // The word comes in reply.cycle at the earliest; OUT follows the state after it.
          declareStateEnd(std::max(reply.cycle, lastStateCycle()));
          return;
        }
        consumeWordIn<kTraced>(reply.cycle);
      }
      stepState<kTraced>();
    }
    offerResult();
  }

  // The state of localCycle_ asks its group's triangle unit and waits in it until granted; OUT
  // follows the state's own cycles after the grant.
  void awaitUnit() {
    phase_ = Phase::AwaitingShared;
    memory->requestTriangleUnit(index_, localCycle_, *this);
    declareStateEnd(lastStateCycle());
  }

  // The current state, waiting for a shared resource, ends in `stateEnd` at the earliest: OUT
  // follows no earlier, and a job no earlier than the cycle after. Forced inline: the stepping
  // loop ran it inline before it became a function of its own (a call per shared read).
  [[gnu::always_inline]] inline void declareStateEnd(uint64_t stateEnd) {
    out_->noOfferBefore(stateEnd + 1);
    in_->notReadyBefore(stateEnd + 2);
  }

  // The current state's cycle: the word it reads, if any, is there by now. Forced inline, with
  // the state machine's step: it runs once per simulated state, and a call costs a fifth of a
  // state.
  template <bool kTraced>
  [[gnu::always_inline]] inline void stepState() {
    const uint32_t cycles = Kind::stateCycles(core_);
    core_.stepInline([this](uint32_t address) { return words_->read(address); });
    localCycle_ += cycles;
    if (kTraced)
      trace_->record(stackSignal_, localCycle_, static_cast<uint64_t>(core_.stackSize()));
  }

  // The read of the current state in its L1. Out of line: inlined, the lookup makes the stepping
  // loop slower.
  template <bool kTraced>
  [[gnu::noinline]] PrivateRead lookUp(uint32_t address) {
    const L1Lookup reply = l1_->lookup(address, localCycle_);
    if (kTraced) memory->tracePrivateLookup(index_, localCycle_);
    return {reply.hit, reply.cycle};
  }

  // The state issued its read in localCycle_ and gets the word in dataCycle: BLOCKED from the
  // state's last cycle to then.
  template <bool kTraced>
  void consumeWordIn(uint64_t dataCycle) {
    if (dataCycle <= lastStateCycle()) return;
    if (kTraced) traceState(lastStateCycle() + 1, Kind::kBlockedState);
    waitForWord(dataCycle);
  }

  // The state ends in dataCycle if that is after its last cycle: kept as a later first cycle, so
  // that stepState() moves on to the cycle after the state's end.
  void waitForWord(uint64_t dataCycle) {
    const uint64_t stateEnd = std::max(dataCycle, lastStateCycle());
    blocked_ += stateEnd - lastStateCycle();
    localCycle_ = stateEnd - (Kind::stateCycles(core_) - 1);
  }

  // The current state's last cycle. (The kind's stateCycles() is read where needed, not kept: for
  // a kind whose states all take one cycle it is a constant, and the loop stays as fast.)
  uint64_t lastStateCycle() const { return localCycle_ + (Kind::stateCycles(core_) - 1); }

  void offerResult() {
    outCycle_ = localCycle_;
    traceState(outCycle_, Kind::kOutState);
    CoreResult result{ids_, CoreKindResult(std::in_place_type<typename Kind::Result>),
                      static_cast<uint32_t>(blocked_)};
    Kind::writeResult(idWord_, core_, *std::get_if<typename Kind::Result>(&result.result));
    statistics_.busyCycles += core_.cost();
    statistics_.blockedCycles += blocked_;
    Kind::count(core_, statistics_);
    phase_ = Phase::Out;
    if (!combinational_ || unitShared_) memory->coreOffering(index_, outCycle_);
    in_->notReadyBefore(outCycle_ + 1);
    out_->offer(result, outCycle_);
  }

  // The result manager took the result in K: idle and ready again from K + 1.
  void handOver() {
    const uint64_t idle = out_->lastTransfer() + 1;
    statistics_.outCycles += idle - outCycle_;
    core_.finish();
    traceState(idle, Kind::kIdleState);
    phase_ = Phase::Idle;
    in_->readyFrom(idle);
  }

  void traceState(uint64_t cycle, uint64_t code) {
    if (trace_) trace_->record(stateSignal_, cycle, code);
  }

  int index_;
  typename Kind::Behaviour core_;
  TransferChannel<CoreJob>* in_ = nullptr;
  TransferChannel<CoreResult>* out_ = nullptr;
  Phase phase_ = Phase::Idle;
  PayloadIds ids_;  // of the current job, for its result
  uint32_t idWord_ = 0;
  uint64_t localCycle_ = 0;  // the first cycle of the core's current state
  uint64_t outCycle_ = 0;
  uint64_t blocked_ = 0;  // blocked cycles of the current job
  const typename Kind::Memory* words_ = nullptr;
  bool combinational_ = false;
  bool unitShared_ = false;      // its triangle unit is shared: a test waits for its grant
  L1CacheTiming* l1_ = nullptr;  // null for the combinational ROM
  CycleTrace* trace_;
  int stateSignal_ = CycleTrace::kNoSignal, stackSignal_ = CycleTrace::kNoSignal;
};

}  // namespace rtu
