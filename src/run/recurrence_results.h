#pragma once
// A run from the recurrence's cycles (src/rtu/rtu_recurrence.h) and each job's result, as
// simulateRtu returns one: results in the host's order with their arrival cycles, and the
// statistics (core times, scheduler waits, result buffers) the cycles imply. The analytic run
// (analytic_run.h) and the loosely-timed model (lt_simulation.h) answer through it.

#include <cstdint>
#include <vector>

#include "rtu/rtu_recurrence.h"
#include "run/rtu_simulation.h"

namespace rtu {

// `results` and `blocked` by job index; `blocked` (cycles BLOCKED on memory, W_i = cost +
// blocked) empty for ideal memory. The statistics' model, memory counts and host seconds are the
// caller's to fill.
// Taken by value: the columns are rearranged in place (callers move them in). The loosely-timed
// model, which keeps no columns, counts through RecurrenceStatistics (recurrence_statistics.h).
RtuRun recurrenceResults(RecurrenceRun timing, std::vector<CoreKindResult> results,
                         std::vector<uint32_t> blocked, const RtuConfig& config);

}  // namespace rtu
