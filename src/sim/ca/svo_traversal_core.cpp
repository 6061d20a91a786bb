#include "sim/ca/svo_traversal_core.h"

#include "kinds/svo/golden_model.h"

namespace rtu {

SvoTraversalCore::SvoTraversalCore(sc_core::sc_module_name name,
                                   DecisionPump& pump, int index, FixedFormat format,
                                   int stackFrames, CycleTrace* trace)
    : sc_core::sc_module(name),
      Agent(pump),
      index_(index),
      core_(FixedArith{format}, stackFrames),
      trace_(trace) {
  if (trace_) {
    stateSignal_ = trace_->declare(this->name(), "state", 3, kCoreStateNames);
    stackSignal_ = trace_->declare(this->name(), "stack_depth", 7);
  }
}

void SvoTraversalCore::bind(TransferChannel<CoreJob>& in, TransferChannel<CoreResult>& out) {
  in_ = &in;
  out_ = &out;
  traceState(0, static_cast<uint64_t>(CoreState::Idle));
  in_->readyFrom(0);
}

void SvoTraversalCore::end_of_elaboration() {
  words_ = &memory->backingStore();
  combinational_ = memory->combinational();
  l1_ = memory->privateCache(index_);
}

void SvoTraversalCore::decide() {
  in_->collectDelivered([this](uint64_t cycle, const CoreJob& job) {
    start(cycle, job);
    run();
  });
  if (phase_ != Phase::Out) return;
  if (out_->collectTaken())
    handOver();
  else if (out_->readyBound() > outCycle_ && in_->readyBound() < out_->readyBound() + 1)
    in_->notReadyBefore(out_->readyBound() + 1);  // the result manager takes it then at the earliest
}

// The current state's cycle: the word it reads, if any, is there by now.
template <bool kTraced>
inline void SvoTraversalCore::stepState() {
  core_.step([this](uint32_t address) { return words_->read(address); });
  ++localCycle_;
  if (kTraced) trace_->record(stackSignal_, localCycle_, static_cast<uint64_t>(core_.stackSize()));
}

// The shared level served the request: the word is there in `dataCycle`. (Called while the pump
// runs: what the core decides puts others on it.)
void SvoTraversalCore::sharedReplied(uint64_t dataCycle) {
  waitForWord(dataCycle);
  run(true);
}

void SvoTraversalCore::start(uint64_t dispatch, const CoreJob& job) {
  ids_ = job.ids;
  idWord_ = job.idWord;
  core_.start(job.t0, job.t1, job.a, job.root);
  localCycle_ = dispatch + 1;
  blocked_ = 0;
  ++statistics_.jobs;
}

// Steps the state machine (first the current state, if its word is there) until OUT or until a
// read needs the shared level. The loop is compiled with and without the trace's records, so
// that an untraced run does not test for the trace in every state.
void SvoTraversalCore::run(bool wordThere) {
  if (trace_)
    steps<true>(wordThere);
  else
    steps<false>(wordThere);
}

template <bool kTraced>
void SvoTraversalCore::steps(bool wordThere) {
  if (wordThere) stepState<kTraced>();
  while (core_.busy()) {
    if (kTraced) traceState(localCycle_, static_cast<uint64_t>(core_.state()));
    if (!combinational_ && core_.readsMemory()) {
      const uint32_t address = core_.memoryAddress();
      const PrivateRead reply = lookUp<kTraced>(address);
      if (!reply.hit) {
        // BLOCKED until the shared level answers. Recorded now, as a trace takes no record behind
        // simulated time and the core resumes only in reply.cycle. (Should the word come in
        // this very cycle, the next state's record in the same cycle replaces it.)
        traceState(localCycle_ + 1, kBlockedStateCode);
        phase_ = Phase::AwaitingShared;
        memory->requestShared(index_, address, reply.cycle, *this);
        // The word comes in reply.cycle at the earliest; OUT follows the state after it.
        out_->noOfferBefore(reply.cycle + 1);
        in_->notReadyBefore(reply.cycle + 2);
        return;
      }
      consumeWordIn<kTraced>(reply.cycle);
    }
    stepState<kTraced>();
  }
  offerResult();
}

// The read of the current state in its L1.
template <bool kTraced>
SvoTraversalCore::PrivateRead SvoTraversalCore::lookUp(uint32_t address) {
  const L1Lookup reply = l1_->lookup(address, localCycle_);
  if (kTraced) memory->tracePrivateLookup(index_, localCycle_);
  return {reply.hit, reply.cycle};
}

// The state issued its read in localCycle_ and gets the word in dataCycle: BLOCKED in between.
template <bool kTraced>
void SvoTraversalCore::consumeWordIn(uint64_t dataCycle) {
  if (dataCycle == localCycle_) return;
  if (kTraced) traceState(localCycle_ + 1, kBlockedStateCode);
  waitForWord(dataCycle);
}

void SvoTraversalCore::waitForWord(uint64_t dataCycle) {
  blocked_ += dataCycle - localCycle_;
  localCycle_ = dataCycle;
}

void SvoTraversalCore::offerResult() {
  outCycle_ = localCycle_;
  traceState(outCycle_, static_cast<uint64_t>(CoreState::Out));
  CoreResult result{ids_, makeResult(idWord_, core_), static_cast<uint32_t>(blocked_)};
  statistics_.busyCycles += core_.cost();
  statistics_.blockedCycles += blocked_;
  if (core_.stackOverflow()) ++statistics_.stackOverflows;
  if (core_.tOverflow()) ++statistics_.tOverflows;
  phase_ = Phase::Out;
  if (!combinational_) memory->coreOffering(index_, outCycle_);
  in_->notReadyBefore(outCycle_ + 1);
  out_->offer(result, outCycle_);
}

// The result manager took the result in K: IDLE and ready again from K + 1.
void SvoTraversalCore::handOver() {
  const uint64_t idle = out_->lastTransfer() + 1;
  statistics_.outCycles += idle - outCycle_;
  core_.finish();
  traceState(idle, static_cast<uint64_t>(CoreState::Idle));
  phase_ = Phase::Idle;
  in_->readyFrom(idle);
}

void SvoTraversalCore::traceState(uint64_t cycle, uint64_t code) {
  if (trace_) trace_->record(stateSignal_, cycle, code);
}

}  // namespace rtu
