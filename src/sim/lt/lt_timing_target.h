#pragma once
// The forward interface of a loosely-timed target that times every access (a cache level). The
// target is its socket's interface itself, bound to a plain tlm::tlm_target_socket:
// tlm_utils' simple and passthrough target sockets dispatch through an object of their own and a
// member pointer, about 30 instructions an access, a tenth of a cached word read.
//   b_transport       the derived target's;
//   nb_transport_fw   completes at once through b_transport, as the base protocol allows;
//   DMI               none: every access must be timed;
//   transport_dbg     none, unless the derived target serves one.

#include <tlm>

namespace rtu {

class LtTimingTarget : public tlm::tlm_fw_transport_if<> {
 public:
  tlm::tlm_sync_enum nb_transport_fw(tlm::tlm_generic_payload& trans, tlm::tlm_phase& phase,
                                     sc_core::sc_time& delay) override {
    b_transport(trans, delay);
    phase = tlm::BEGIN_RESP;
    return tlm::TLM_COMPLETED;
  }
  bool get_direct_mem_ptr(tlm::tlm_generic_payload&, tlm::tlm_dmi& dmi) override {
    dmi.allow_none();
    return false;
  }
  unsigned int transport_dbg(tlm::tlm_generic_payload&) override { return 0; }
};

}  // namespace rtu
