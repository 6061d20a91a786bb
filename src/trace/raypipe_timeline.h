#pragma once
// The ray pipe's timeline (issue 29 §2; docs/raypipe.md, "Traces and timeline"), in the Chrome
// trace-event JSON of src/trace/timeline_writer.h, which Perfetto and chrome://tracing open. The
// pipe has no core that owns a ray: its rays share every unit, and each holds one of the shader's
// ray ids from the cycle SINT takes it to the cycle it leaves the shader. So:
// - one track per ray id (`ray_id 000` ... `ray_id 511`), and on it one slice per ray, `pixel N`
//   (the seed's pixel id), from the cycle the shader gave it the id to the cycle it left the
//   shader (its exit, included);
// - counters: `ray ids held` (rays between those two cycles) and `waiting for an id` (pixels the
//   PRG took that have no ray id yet).
// Built from a timed run's per-ray cycles (RaypipeCycleRun), which are exact; the window keeps the
// rays given their id in it and the counters in it. Times in microseconds at the pipe's clock.

#include <cstdint>

#include "raypipe/raypipe_run.h"
#include "trace/timeline_writer.h"

namespace rtu {

// Writes the timeline of `run` (or with options.countOnly only counts it) and returns its bytes;
// throws std::runtime_error when the file could not be written.
uint64_t writeRaypipeTimeline(const RaypipeCycleRun& run, const TimelineOptions& options,
                              uint64_t periodPs, int raysInFlight);

}  // namespace rtu
