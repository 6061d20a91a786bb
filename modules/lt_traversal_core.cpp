#include "lt_traversal_core.h"

#include <stdexcept>
#include <string>

#include "golden_model.h"

namespace rtu {

LtTraversalCore::LtTraversalCore(sc_core::sc_module_name name, int index, FixedFormat format,
                                 int stackFrames, const LtTime& time)
    : sc_core::sc_module(name),
      memory("memory"),
      jobs("jobs"),
      results("results"),
      index_(index),
      time_(time),
      core_(FixedArith{format}, stackFrames) {
  read_.set_read();
  read_.set_data_ptr(reinterpret_cast<unsigned char*>(&word_));
  read_.set_data_length(sizeof word_);
  read_.set_streaming_width(sizeof word_);
  SC_HAS_PROCESS(LtTraversalCore);
  SC_THREAD(run);
}

void LtTraversalCore::run() {
  acquireDmi();
  quantum_.reset();
  uint64_t idleFrom = 0;
  LtDispatch dispatch;
  while (jobs->take(index_, idleFrom, dispatch)) {
    const CoreJob& job = dispatch.job;
    core_.start(job.t0, job.t1, job.a, job.root);
    uint32_t blocked = 0;
    const uint64_t out = traverse(dispatch.cycle, blocked);
    const CoreResult result{job.ids, makeResult(job.idWord, core_), blocked};
    core_.finish();
    idleFrom = results->handOver(index_, out, result);
    keepQuantum(idleFrom);
  }
}

void LtTraversalCore::acquireDmi() {
  tlm::tlm_dmi dmi;
  read_.set_address(0);
  if (!memory->get_direct_mem_ptr(read_, dmi) || !dmi.is_read_allowed()) return;
  dmi_ = true;
  direct_ = SvoMemory(reinterpret_cast<const uint32_t*>(dmi.get_dmi_ptr()),
                      static_cast<size_t>((dmi.get_end_address() + 1) / 4));
}

uint64_t LtTraversalCore::traverse(uint64_t dispatch, uint32_t& blocked) {
  uint64_t cycle = dispatch + 1;
  if (dmi_) {
    while (core_.busy()) {
      core_.step([this](uint32_t address) { return direct_.read(address); });
      ++cycle;
    }
    return cycle;
  }
  while (core_.busy()) {
    if (core_.readsMemory()) {
      const uint64_t issued = cycle;
      const uint32_t word = readWord(core_.memoryAddress(), cycle);
      blocked += static_cast<uint32_t>(cycle - issued);
      core_.step([word](uint32_t) { return word; });
    } else {
      core_.step([](uint32_t address) -> uint32_t {
        throw std::logic_error("state read word " + std::to_string(address) + " unannounced");
      });
    }
    ++cycle;
  }
  return cycle;
}

uint32_t LtTraversalCore::readWord(uint32_t address, uint64_t& cycle) {
  read_.set_address(uint64_t{address} * 4);
  read_.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  sc_core::sc_time delay = time_.delayTo(cycle);
  memory->b_transport(read_, delay);
  if (read_.is_response_error())
    throw std::runtime_error(std::string(name()) + ": memory read failed: " +
                             read_.get_response_string());
  cycle = time_.cycleAt(delay);
  return word_;
}

// Local time is the cycle the core is idle from; past the quantum, the core yields.
void LtTraversalCore::keepQuantum(uint64_t cycle) {
  quantum_.set(time_.delayTo(cycle));
  if (quantum_.need_sync()) quantum_.sync();
}

}  // namespace rtu
