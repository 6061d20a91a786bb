#pragma once
// A core's private L1 as a loosely-timed TLM-2.0 target: a word read at the cycle its delay
// annotates returns the word (from the read-only image: the cache holds tags, as cache_array.h
// says) with the delay to the cycle the word is there. Timing: l1_cache_timing.h; a miss reads
// the line from the L2 through `next`. One core reads it, in its own cycle order, so the L1 is
// exact; only the shared L2 sees requests out of order.
//
// The cache is its socket's forward interface itself (a plain tlm_target_socket), not a
// tlm_utils::simple_target_socket: that one's dispatch through its own process and a member
// pointer cost about 30 instructions a word, a tenth of a read. It has no DMI (every read is
// timed); nb_transport_fw completes at once, as the base protocol allows.

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "l1_cache_timing.h"
#include "lt_time.h"
#include "svo_memory.h"

namespace rtu {

class LtL1Cache : public sc_core::sc_module, public tlm::tlm_fw_transport_if<> {
 public:
  tlm::tlm_target_socket<> socket;
  tlm_utils::simple_initiator_socket<LtL1Cache> next;

  LtL1Cache(sc_core::sc_module_name name, const CacheConfig& config, SvoMemory words,
            const LtTime& time);

  const CacheStats& statistics() const { return timing_.stats(); }

  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) override;
  tlm::tlm_sync_enum nb_transport_fw(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay) override;
  bool get_direct_mem_ptr(tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi) override;
  unsigned int transport_dbg(tlm::tlm_generic_payload& trans) override;

 private:

  SvoMemory words_;
  LtTime time_;
  L1CacheTiming timing_;
  uint64_t hitCycles_;
  sc_core::sc_time hitDelay_;
  LineRead lineRead_;
};

}  // namespace rtu
