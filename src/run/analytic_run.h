#pragma once
// The cycle-exact answer without simulating: for configurations the recurrence of
// src/rtu/rtu_recurrence.h models (ideal memory, no reorder buffer, no trace, host links unlimited
// or paced), the golden model gives each ray's result and cost and the recurrence every cycle.
// The run, statistics included, equals simulateRtu's (tests/test_analytic_run.cpp); `rtusim fps`
// takes this path where it applies.

#include <optional>
#include <string>
#include <vector>

#include "run/rtu_simulation.h"

namespace rtu {

// Why the recurrence cannot answer for this configuration, or nothing when it can.
std::optional<std::string> whyNotAnalytic(const RtuConfig& config);

// Throws std::invalid_argument when whyNotAnalytic says why, or for an impossible configuration.
RtuRun runAnalytic(const WordMemory& memory, const std::vector<HostRecord>& records,
                   const RtuConfig& config);
RtuRun runAnalytic(const WordMemory& memory, const std::vector<TValueRecord>& jobs,
                   const RtuConfig& config);

// The golden traversal of each record by the kind config.core, untimed, in record order: the
// results the timed models must equal (no check of the RTU's settings; a record the kind does not
// take throws std::invalid_argument).
std::vector<CoreKindResult> traceGolden(const WordMemory& memory,
                                        const std::vector<HostRecord>& records,
                                        const RtuConfig& config);
// The same results, each handed to `take` as soon as it is traced and none kept (the records
// made one at a time when the source makes them): a frame of any size in little memory.
void traceGolden(const WordMemory& memory, const RecordSource& records, const RtuConfig& config,
                 const ResultTaker& take);

}  // namespace rtu
