#pragma once
// Each simulation (cycle-accurate or loosely-timed) runs in its own SystemC kernel: SystemC
// cannot elaborate again once a simulation has started. The previous kernel is left allocated:
// deleting it is not supported by SystemC 2.3.

namespace rtu {

void freshKernel();

}  // namespace rtu
