#pragma once
// Each simulation (cycle-accurate or loosely-timed) runs in its own SystemC kernel: SystemC
// cannot elaborate again once a simulation has started. The previous kernel is left allocated:
// deleting it is not supported by SystemC 2.3.

#include <systemc>

namespace rtu {

void freshKernel();

// sc_start() to the end of the simulation, or for `duration`: every simulation starts here, so
// that the kernel leaves the process as it found it (sc_kernel.cpp).
void simulate();
void simulateFor(const sc_core::sc_time& duration);

}  // namespace rtu
