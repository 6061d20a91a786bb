#pragma once
// `render --architecture raypipe --trace/--timeline` (issue 29 §2; docs/raypipe.md, "Traces and
// timeline"): the timed pipe's cycle trace (sim/raypipe/pipe_trace.h: every unit's valid, stall
// and ray id, every FIFO's count and head) and its timeline (trace/raypipe_timeline.h: a track per
// ray id), as the RTU's are shaped: --trace-from/--trace-to, --trace-scope, --trace-signals,
// --trace-clock, --trace-time, and --trace-ray N (the N-th ray of the PRG's issue order, from the
// cycle the PRG took it to the cycle it left the shader). Measured first (docs/waveforms.md, "Size
// first"): a counting run of the model prints each file's size and refuses one above
// --trace-max-mb before anything is written.

#include <cstdint>
#include <iosfwd>
#include <vector>

#include "app/run_outputs.h"
#include "raypipe/primary_rays.h"
#include "raypipe/raypipe_config.h"
#include "raypipe/raypipe_run.h"

namespace rtu {

// Writes the trace and the timeline `outputs` ask for of the frame whose untraced timed run is
// `run` (it gives --trace-ray's window and the timeline's rays; the traced run repeats it cycle
// for cycle), and says so on `out`.
void writeRaypipeTraces(const RaypipeConfig& config, const std::vector<uint32_t>& image,
                        const std::vector<PrimaryRay>& rays, const RaypipeCycleRun& run,
                        const RunOutputs& outputs, std::ostream& out);

}  // namespace rtu
