#pragma once
// The scheduler's policies (thesis 6.2.2, appendix C.3), shared by the SystemC scheduler and the
// analytic recurrence:
//  - cyclic first-available (the RTL): a select counter advances every cycle from reset; the job
//    goes to the selected core when that core is ready;
//  - round-robin: cores in turn; the job waits for the next core in line;
//  - first-available: the lowest-numbered ready core, in the same cycle.

#include <string>

namespace rtu {

enum class SchedulerPolicy { CyclicFirstAvailable, RoundRobin, FirstAvailable };
// "cfa", "rr" or "fa"; throws std::invalid_argument naming the choices.
SchedulerPolicy parseSchedulerPolicy(const std::string& name);
const char* toString(SchedulerPolicy policy);

}  // namespace rtu
