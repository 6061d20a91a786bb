#pragma once
// The thesis' ideal ROM as a loosely-timed TLM-2.0 target: every word in the cycle it is read.
// It grants DMI to the whole image, so the cores read it directly (no transaction per word);
// b_transport serves initiators that do not use DMI, with no delay.

#include <tlm>
#include <tlm_utils/multi_passthrough_target_socket.h>

#include "svo_memory.h"

namespace rtu {

class LtRom : public sc_core::sc_module {
 public:
  tlm_utils::multi_passthrough_target_socket<LtRom> socket;  // every core binds it

  LtRom(sc_core::sc_module_name name, SvoMemory words);

 private:
  void b_transport(int id, tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);
  bool get_direct_mem_ptr(int id, tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi);

  SvoMemory words_;
};

// Serves a read of one 32-bit word from `words` (the image is read-only): the word at the
// payload's byte address, 0 past the image, as SvoMemory reads. Other commands are errors.
void serveWordRead(const SvoMemory& words, tlm::tlm_generic_payload& trans);

}  // namespace rtu
