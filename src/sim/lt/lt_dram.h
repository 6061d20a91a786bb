#pragma once
// The DRAM behind the L2 as a loosely-timed TLM-2.0 target: a read of a line (the payload's
// length in bytes, within one line of `lineBytes`, the L2's: lt_word_read.h), issued at the cycle
// its delay annotates, returns with the delay to the cycle its last byte arrived. Timing:
// dram_channel.h with RequestOrder::Any, as the reads come one traversal after another, out of
// cycle order (src/sim/lt/lt_top.h).

#include <tlm>
#include <tlm_utils/simple_target_socket.h>

#include "sim/lt/lt_time.h"
#include "sim/memory/dram_channel.h"

namespace rtu {

class LtDram : public sc_core::sc_module {
 public:
  tlm_utils::simple_target_socket<LtDram> socket;

  LtDram(sc_core::sc_module_name name, const DramConfig& config, uint32_t lineBytes,
         const LtTime& time);

  const DramStats& statistics() const { return channel_.stats(); }

 private:
  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);

  DramChannel channel_;
  LtTime time_;
  uint32_t lineBytes_;
  uint64_t forgottenAt_ = 0;  // the cycle of the last forgetBefore
};

}  // namespace rtu
