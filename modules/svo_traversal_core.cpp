#include "svo_traversal_core.h"

#include "golden_model.h"

namespace rtu {

SvoTraversalCore::SvoTraversalCore(sc_core::sc_module_name name, const CycleClock& clock,
                                   int index, FixedFormat format, int stackFrames,
                                   CycleTrace* trace)
    : sc_core::sc_module(name),
      clock_(clock),
      index_(index),
      core_(FixedArith{format}, stackFrames),
      wake_(clock),
      trace_(trace) {
  if (trace_) {
    stateSignal_ = trace_->declare(this->name(), "state", 3, kCoreStateNames);
    stackSignal_ = trace_->declare(this->name(), "stack_depth", 7);
  }
}

void SvoTraversalCore::end_of_elaboration() {
  words_ = &memory->backingStore();
  combinational_ = memory->combinational();
  spawnMethod("evaluate", [this] { evaluate(); },
              {&in->edge(), &out->edge(), &memory->sharedReplied(index_), &wake_.event()});
}

void SvoTraversalCore::evaluate() {
  const uint64_t now = clock_.now();
  switch (phase_) {
    case Phase::Idle:
      if (now > 0 && in->transferredIn(now - 1)) {
        start(now);
        run();
        return;
      }
      in->setReady(true);
      traceState(now, static_cast<uint64_t>(CoreState::Idle));
      return;
    case Phase::AwaitingShared:
      if (!sharedRequested_) {
        memory->requestShared(index_, sharedAddress_);
        sharedRequested_ = true;
        return;
      }
      resumeAfterSharedRead();
      run();
      return;
    case Phase::ResultDue:
      offerResult();
      return;
    case Phase::Out:
      handOver(now);
      return;
  }
}

void SvoTraversalCore::start(uint64_t now) {
  job_ = in->transferred();
  in->setReady(false);
  core_.start(job_.t0, job_.t1, job_.a, job_.root);
  localCycle_ = now;
  blocked_ = 0;
  ++statistics_.jobs;
}

// Steps the state machine until OUT or until a read needs the shared level.
void SvoTraversalCore::run() {
  while (core_.busy()) {
    traceState(localCycle_, static_cast<uint64_t>(core_.state()));
    if (!combinational_ && core_.readsMemory()) {
      const uint32_t address = core_.memoryAddress();
      const MemoryReply reply = memory->lookup(index_, address, localCycle_);
      if (!reply.known) {
        // BLOCKED until the shared level answers. Recorded now, as a trace takes no record behind
        // simulated time and the core resumes only in reply.cycle. (Should the word come in
        // this very cycle, the next state's record in the same cycle replaces it.)
        traceState(localCycle_ + 1, kBlockedStateCode);
        sharedAddress_ = address;
        sharedRequested_ = false;
        phase_ = Phase::AwaitingShared;
        wake_.at(reply.cycle);
        return;
      }
      consumeWordIn(reply.cycle);
    }
    stepState();
  }
  outCycle_ = localCycle_;
  traceState(outCycle_, static_cast<uint64_t>(CoreState::Out));
  phase_ = Phase::ResultDue;
  wake_.at(outCycle_);
}

void SvoTraversalCore::resumeAfterSharedRead() {
  waitForWord(memory->sharedReplyCycle(index_));
  stepState();
}

// The current state's cycle: the word it reads, if any, is there by now.
void SvoTraversalCore::stepState() {
  core_.step([this](uint32_t address) { return words_->read(address); });
  ++localCycle_;
  if (trace_) trace_->record(stackSignal_, localCycle_, static_cast<uint64_t>(core_.stackSize()));
}

// The state issued its read in localCycle_ and gets the word in dataCycle: BLOCKED in between.
void SvoTraversalCore::consumeWordIn(uint64_t dataCycle) {
  if (dataCycle == localCycle_) return;
  traceState(localCycle_ + 1, kBlockedStateCode);
  waitForWord(dataCycle);
}

void SvoTraversalCore::waitForWord(uint64_t dataCycle) {
  blocked_ += dataCycle - localCycle_;
  localCycle_ = dataCycle;
}

void SvoTraversalCore::offerResult() {
  CoreResult result{job_.sequence, makeResult(job_.idWord, core_), static_cast<uint32_t>(blocked_)};
  statistics_.busyCycles += core_.cost();
  statistics_.blockedCycles += blocked_;
  if (core_.stackOverflow()) ++statistics_.stackOverflows;
  if (core_.tOverflow()) ++statistics_.tOverflows;
  out->offer(result);
  phase_ = Phase::Out;
}

void SvoTraversalCore::handOver(uint64_t now) {
  if (!out->transferredIn(now - 1)) return;
  statistics_.outCycles += now - outCycle_;
  core_.finish();
  out->withdraw();
  in->setReady(true);
  traceState(now, static_cast<uint64_t>(CoreState::Idle));
  phase_ = Phase::Idle;
}

void SvoTraversalCore::traceState(uint64_t cycle, uint64_t code) {
  if (trace_) trace_->record(stateSignal_, cycle, code);
}

}  // namespace rtu
