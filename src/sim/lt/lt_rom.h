#pragma once
// The thesis' ideal ROM as a loosely-timed TLM-2.0 target: every word in the cycle it is read.
// It grants DMI to the whole image, so the cores read it directly (no transaction per word);
// b_transport serves initiators that do not use DMI, with no delay: whole words within an aligned
// block of `lineBytes` (lt_word_read.h). The ROM has no lines; the top gives it the cores' access
// width, so that it refuses an access not aligned to its size, as the caches refuse one that
// crosses their line.

#include <cstdint>

#include <tlm>
#include <tlm_utils/multi_passthrough_target_socket.h>

#include "rtu/word_memory.h"

namespace rtu {

class LtRom : public sc_core::sc_module {
 public:
  tlm_utils::multi_passthrough_target_socket<LtRom> socket;  // every core binds it

  LtRom(sc_core::sc_module_name name, WordMemory words, uint32_t lineBytes);

 private:
  void b_transport(int id, tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);
  bool get_direct_mem_ptr(int id, tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi);

  WordMemory words_;
  uint32_t lineBytes_;
};

}  // namespace rtu
