#pragma once
// The shared L2 as a loosely-timed TLM-2.0 target, bound by every core's L1: a read within one of
// its lines (lt_word_read.h; an L1 reads its own line) at the cycle its delay annotates returns
// with the delay to the cycle the line is at the L2's output. Timing: l2_cache_timing.h with
// RequestOrder::Any (the cores' requests come one traversal after another, out of cycle order:
// src/sim/lt/lt_top.h); its misses go to the DRAM target through `dram`. It is its socket's
// interface itself (lt_timing_target.h); the socket takes any number of initiators, and the L2
// needs no backward path to them.

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "sim/lt/lt_time.h"
#include "sim/lt/lt_timing_target.h"
#include "sim/memory/l2_cache_timing.h"

namespace rtu {

class LtL2Cache : public sc_core::sc_module, public LtTimingTarget {
 public:
  tlm::tlm_target_socket<32, tlm::tlm_base_protocol_types, 0> socket;  // every L1 binds it
  tlm_utils::simple_initiator_socket<LtL2Cache> dram;

  LtL2Cache(sc_core::sc_module_name name, const MemoryConfig& config, const LtTime& time);

  // The cache's counts; the DRAM's are the DRAM target's.
  L2Stats statistics() const { return timing_.stats(); }

  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) override;

 private:
  LtTime time_;
  uint64_t forgottenAt_ = 0;  // the cycle of the last forgetBefore
  L2CacheTiming timing_;
  uint32_t lineBytes_;
  LineRead dramRead_;
};

}  // namespace rtu
