#pragma once
// The thesis' ideal ROM as a loosely-timed TLM-2.0 target: every word in the cycle it is read.
// It grants DMI to the whole image, so the cores read it directly (no transaction per word);
// b_transport serves initiators that do not use DMI, with no delay.

#include <cstring>

#include <tlm>
#include <tlm_utils/multi_passthrough_target_socket.h>

#include "rtu/word_memory.h"

namespace rtu {

class LtRom : public sc_core::sc_module {
 public:
  tlm_utils::multi_passthrough_target_socket<LtRom> socket;  // every core binds it

  LtRom(sc_core::sc_module_name name, WordMemory words);

 private:
  void b_transport(int id, tlm::tlm_generic_payload& trans, sc_core::sc_time& delay);
  bool get_direct_mem_ptr(int id, tlm::tlm_generic_payload& trans, tlm::tlm_dmi& dmi);

  WordMemory words_;
};

// Serves a read of one 32-bit word from `words` (the image is read-only): the word at the
// payload's byte address, 0 past the image, as WordMemory reads. Other commands are errors.
// Inline: the L1 serves every word a cached run's cores read.
inline void serveWordRead(const WordMemory& words, tlm::tlm_generic_payload& trans) {
  if (trans.get_command() != tlm::TLM_READ_COMMAND || trans.get_data_length() != 4) {
    trans.set_response_status(tlm::TLM_COMMAND_ERROR_RESPONSE);
    return;
  }
  const uint32_t word = words.read(static_cast<uint32_t>(trans.get_address() / 4));
  std::memcpy(trans.get_data_ptr(), &word, sizeof word);
  trans.set_response_status(tlm::TLM_OK_RESPONSE);
}

}  // namespace rtu
