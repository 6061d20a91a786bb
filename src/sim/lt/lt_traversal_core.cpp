#include "sim/lt/lt_core.h"

#include <stdexcept>
#include <string>

#include "kinds/svo/golden_model.h"

namespace rtu {

LtTraversalCore::LtTraversalCore(sc_core::sc_module_name name, TraversalCore<FixedArith>& core,
                                 const LtTime& time)
    : sc_core::sc_module(name), memory("memory"), time_(time), period_(time.period()), core_(core) {
  read_.set_read();
  read_.set_data_ptr(reinterpret_cast<unsigned char*>(&word_));
  read_.set_data_length(sizeof word_);
  read_.set_streaming_width(sizeof word_);
}

// Asked once, at the first job: the targets are bound by then.
void LtTraversalCore::acquireDmi() {
  dmiAsked_ = true;
  tlm::tlm_dmi dmi;
  read_.set_address(0);
  if (!memory->get_direct_mem_ptr(read_, dmi) || !dmi.is_read_allowed()) return;
  dmi_ = true;
  direct_ = WordMemory(reinterpret_cast<const uint32_t*>(dmi.get_dmi_ptr()),
                       static_cast<size_t>((dmi.get_end_address() + 1) / 4));
}

uint32_t LtTraversalCore::traverse(const CoreJob& job, uint64_t initCycle,
                                   TraversalResult& result) {
  if (!dmiAsked_) acquireDmi();
  SvoKind::start(core_, *std::get_if<SvoJob>(&job.job));
  uint32_t blocked = 0;
  if (dmi_)
    while (core_.busy()) core_.step([this](uint32_t address) { return direct_.read(address); });
  else
    blocked = stepThroughSocket(initCycle);
  writeResult(job.idWord, core_, result);
  core_.finish();
  return blocked;
}

inline uint32_t LtTraversalCore::readWord(uint32_t address, sc_core::sc_time& delay) {
  read_.set_address(uint64_t{address} * 4);
  read_.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  memory->b_transport(read_, delay);
  if (read_.is_response_error()) failRead();
  return word_;
}

// The state's cycle is kept as a delay after simulated time: a cycle is an addition, and a read
// returns the delay to the cycle its word is there. The cycles past one per state were blocked.
uint32_t LtTraversalCore::stepThroughSocket(uint64_t initCycle) {
  TraversalCore<FixedArith>& core = core_;  // in a register: the member is reloaded after a read
  sc_core::sc_time delay = time_.delayTo(initCycle);
  while (core.busy()) {
    core.step([this, &delay](uint32_t address) { return readWord(address, delay); });
    delay += period_;
  }
  return static_cast<uint32_t>(time_.cycleAt(delay) - initCycle - core.cost());
}

void LtTraversalCore::failRead() const {
  throw std::runtime_error(std::string(name()) +
                           ": memory read failed: " + read_.get_response_string());
}

}  // namespace rtu
