#include "sim/kernel/sc_kernel.h"

#include <systemc>

namespace rtu {

void freshKernel() {
  sc_core::sc_curr_simcontext = new sc_core::sc_simcontext();
  sc_core::sc_default_global_context = sc_core::sc_curr_simcontext;
}

}  // namespace rtu
