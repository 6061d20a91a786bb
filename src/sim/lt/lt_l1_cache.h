#pragma once
// A core's private L1 as a loosely-timed TLM-2.0 target: a read of its core's access (the words of
// `accessBytes` aligned to them, lt_word_read.h) at the cycle its delay annotates returns the words
// (from the read-only image: the cache holds tags, as cache_array.h says) with the delay to the
// cycle they are there. Timing: l1_cache_timing.h; a miss reads the line from the L2 through
// `next`. One core reads it, in its own cycle order, so the L1 is exact; only the shared L2 sees
// requests out of order. Its tag store counts picoseconds since the start (l1_cache_timing.h allows
// any unit), those of the delays it is given. It is its socket's interface itself
// (lt_timing_target.h); its debug access reads the words.

#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "rtu/word_memory.h"
#include "sim/lt/lt_time.h"
#include "sim/lt/lt_timing_target.h"
#include "sim/memory/l1_cache_timing.h"

namespace rtu {

class LtL1Cache : public sc_core::sc_module, public LtTimingTarget {
 public:
  tlm::tlm_target_socket<> socket;
  tlm_utils::simple_initiator_socket<LtL1Cache> next;

  // Throws std::invalid_argument when `accessBytes` is not a power of two of a word or more
  // within a line.
  LtL1Cache(sc_core::sc_module_name name, const CacheConfig& config, uint32_t accessBytes,
            WordMemory words, const LtTime& time);

  CacheStats statistics() const { return timing_.stats(); }

  void b_transport(tlm::tlm_generic_payload& trans, sc_core::sc_time& delay) override;
  unsigned int transport_dbg(tlm::tlm_generic_payload& trans) override;

 private:
  // The line of a missing access, requested from the L2 at the delay `request`, allocated; returns
  // the delay to the cycle its words are there.
  sc_core::sc_time fetch(uint32_t word, uint64_t lineAddress, sc_core::sc_time request);

  WordMemory words_;
  LtTime time_;
  L1CacheTiming timing_;
  uint64_t hitPicoseconds_;
  sc_core::sc_time hitDelay_;
  uint32_t accessBytes_, lineBytes_;
  LineRead lineRead_;
};

}  // namespace rtu
