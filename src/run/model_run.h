#pragma once
// Which model answers a run (the `model` setting, `--model`): the golden model, the loosely-timed
// TLM-2.0 model or the cycle-accurate SystemC model (docs/fidelity.md compares them).
//   golden  results bit-exact and untimed; where cycles are asked for, each ray takes its golden
//           cost and the recurrence (src/rtu/rtu_recurrence.h) times the RTU around it with the
//           memory taken as ideal: memory stalls are not in it.
//   lt      results bit-exact; cycles estimated (lt_simulation.h).
//   ca      results bit-exact; cycles exact (the default).

#include <string>
#include <vector>

#include "run/rtu_simulation.h"

namespace rtu {

enum class ModelKind { Golden, LooselyTimed, CycleAccurate };

// "golden", "lt" or "ca"; throws std::invalid_argument naming the choices.
ModelKind parseModelKind(const std::string& name);
const char* toString(ModelKind model);

// Throws std::invalid_argument when the model cannot run `config` (saying why).
RtuRun runModel(ModelKind model, const WordMemory& memory, const std::vector<HostRecord>& records,
                const RtuConfig& config, const RunProgress& progress = {});
RtuRun runModel(ModelKind model, const WordMemory& memory, const std::vector<TValueRecord>& jobs,
                const RtuConfig& config, const RunProgress& progress = {});

// A frame's run that hands each result to `take` (kinds/host_stream.h): the cycle-accurate model
// as it leaves the RTU, keeping none (streamRtu); the loosely-timed model and the golden model's
// timing, whose recurrence orders the whole run, keep them to the end and then hand them over in
// the host's order, and the golden timing reads a made source's records into a vector first. The
// run's results are then empty; its statistics are runModel's.
RtuRun runFrame(ModelKind model, const WordMemory& memory, const RecordSource& records,
                const RtuConfig& config, const ResultTaker& take, const RunProgress& progress = {});

// The golden model's timing: golden costs in the recurrence, memory as ideal.
RtuRun runGoldenTimed(const WordMemory& memory, const std::vector<HostRecord>& records,
                      const RtuConfig& config);

}  // namespace rtu
