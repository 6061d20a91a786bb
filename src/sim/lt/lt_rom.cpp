#include "sim/lt/lt_rom.h"

#include "sim/lt/lt_word_read.h"

namespace rtu {

LtRom::LtRom(sc_core::sc_module_name name, WordMemory words, uint32_t lineBytes)
    : sc_core::sc_module(name), socket("socket"), words_(words), lineBytes_(lineBytes) {
  socket.register_b_transport(this, &LtRom::b_transport);
  socket.register_get_direct_mem_ptr(this, &LtRom::get_direct_mem_ptr);
}

void LtRom::b_transport(int, tlm::tlm_generic_payload& trans, sc_core::sc_time&) {
  if (acceptWordRead(trans, lineBytes_)) serveWordRead(words_, trans);
  trans.set_dmi_allowed(true);
}

bool LtRom::get_direct_mem_ptr(int, tlm::tlm_generic_payload&, tlm::tlm_dmi& dmi) {
  dmi.allow_read();
  dmi.set_dmi_ptr(reinterpret_cast<unsigned char*>(const_cast<uint32_t*>(words_.data())));
  dmi.set_start_address(0);
  dmi.set_end_address(words_.size() * 4 - 1);
  dmi.set_read_latency(sc_core::SC_ZERO_TIME);
  return words_.size() > 0;
}

}  // namespace rtu
