#pragma once
// The timed model of seed 001's ray pipe (the Tray Racer, issue 29 §1, §4): the final build R1
// demonstrated (DEMOS/t5.sv with RAYTRACER/raypipe_simple_caches.sv), cycle-exact with the
// per-cycle reference (reference/raypipe_cycles.h) at a cost that follows the rays: each unit is
// called only in a cycle it holds an item or is offered one, and its FIFOs, fixed-latency pipes
// and registers are lazy in time, so nothing happens between a ray's entry into a pipe and its
// exit. docs/raypipe.md, "The timed model", gives the design and why it is exact.
//
// Same inputs and results as the reference (raypipe/raypipe_run.h), the VGA reader's window
// included (RaypipePixelWriter::vgaReadWindow; vga_window.h). Both equal the seed's RTL in every
// recorded exit cycle (tests/test_raypipe_rtl.cpp; docs/raypipe.md, "Against the RTL"). With
// raypipe.cache = set_associative the caches are R1's designed ones (timed_cache.h) in front of
// rtusim's DRAM channel, cycle for cycle the reference's.

#include <vector>

#include "kinds/kd/kd_image.h"
#include "raypipe/raypipe_config.h"
#include "raypipe/raypipe_run.h"
#include "trace/cycle_trace.h"

namespace rtu {

// Throws std::invalid_argument for a configuration the model does not take (as runRaypipeTimed),
// so that a run can refuse it before any work.
void checkRaypipeTimedTakes(const RaypipeConfig& config);

// Runs one frame. Throws std::invalid_argument for a configuration the model does not take (one
// RaypipeConfig::validate refuses, a negative VGA phase), logic_error when the
// pipe breaks one of its own rules (a write to a full FIFO, a ray id used twice, no progress for a
// million cycles). With `trace`, the run's trace goes to it and is finished (pipe_trace.h: every
// unit's valid, stall and ray id, every FIFO's count and head; the save file's marker at the
// first pixel's exit).
RaypipeCycleRun runRaypipeTimed(const RaypipeConfig& config, const KdImage& image,
                                const std::vector<RaypipeCycleRay>& rays,
                                const RaypipeCycleOptions& options = {},
                                CycleTrace* trace = nullptr);

}  // namespace rtu
