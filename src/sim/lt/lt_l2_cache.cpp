#include "sim/lt/lt_l2_cache.h"

#include "sim/lt/lt_word_read.h"

namespace rtu {

LtL2Cache::LtL2Cache(sc_core::sc_module_name name, const MemoryConfig& config, const LtTime& time)
    : sc_core::sc_module(name),
      socket("socket"),
      dram("dram"),
      time_(time),
      timing_(config.l2, config.dram, RequestOrder::Any,
              [this](uint32_t bytes, uint64_t issue) {
                return dramRead_(dram, time_, 0, bytes, issue);
              }),
      lineBytes_(config.l2.lineBytes),
      dramRead_(config.l2.lineBytes) {
  socket.bind(*this);
}

void LtL2Cache::b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
  if (!acceptWordRead(trans, lineBytes_)) return;
  // No request comes for a cycle behind simulated time.
  if (time_.movedSince(forgottenAt_)) timing_.forgetBefore(forgottenAt_);
  const uint64_t ready = timing_.read(trans.get_address(), time_.cycleAt(delay));
  delay = time_.delayTo(ready);
  trans.set_response_status(tlm::TLM_OK_RESPONSE);
}

}  // namespace rtu
