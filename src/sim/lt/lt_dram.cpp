#include "sim/lt/lt_dram.h"

#include "sim/lt/lt_word_read.h"

namespace rtu {

LtDram::LtDram(sc_core::sc_module_name name, const DramConfig& config, uint32_t lineBytes,
               const LtTime& time)
    : sc_core::sc_module(name),
      socket("socket"),
      channel_(config, RequestOrder::Any),
      time_(time),
      lineBytes_(lineBytes) {
  socket.register_b_transport(this, &LtDram::b_transport);
}

void LtDram::b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) {
  if (!acceptWordRead(trans, lineBytes_)) return;
  // No initiator is behind simulated time: bookings that ended before it are of no use.
  if (time_.movedSince(forgottenAt_)) channel_.forgetBefore(forgottenAt_);
  const uint64_t end = channel_.read(trans.get_data_length(), time_.cycleAt(delay));
  delay = time_.delayTo(end);
  trans.set_response_status(tlm::TLM_OK_RESPONSE);
}

}  // namespace rtu
