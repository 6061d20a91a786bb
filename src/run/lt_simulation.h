#pragma once
// Runs the loosely-timed model (lt_top.h) over a frame: the per-ray results are the golden
// model's (the same state machine and job set-up); cycles, core times, scheduler waits and cache
// counts are estimates, measured against the cycle-accurate model in docs/fidelity.md. Returns
// what simulateRtu returns, with statistics.model "lt".

#include <optional>
#include <string>
#include <vector>

#include "run/rtu_simulation.h"

namespace rtu {

// Why the loosely-timed model cannot run this configuration, or nothing when it can.
std::optional<std::string> whyNotLooselyTimed(const RtuConfig& config);

// Throws std::invalid_argument for a configuration whyNotLooselyTimed refuses or that is
// impossible; std::runtime_error for an invalid model header.
RtuRun runLooselyTimed(const WordMemory& memory, const RecordSource& records,
                       const RtuConfig& config, const RunProgress& progress = {});
RtuRun runLooselyTimed(const WordMemory& memory, const std::vector<TValueRecord>& jobs,
                       const RtuConfig& config, const RunProgress& progress = {});
// A run that streams (kinds/host_stream.h), as streamRtu: each result handed to `take` as it
// reaches the host, none kept; the model holds the jobs in flight (lt_top.h), not the frame.
RtuRun streamLooselyTimed(const WordMemory& memory, const RecordSource& records,
                          const RtuConfig& config, const ResultTaker& take,
                          const RunProgress& progress = {});

}  // namespace rtu
