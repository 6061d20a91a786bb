#pragma once
// The per-cycle reference of seed 001's ray pipe (the Tray Racer, issue 29 §3): the final build R1
// demonstrated (DEMOS/t5.sv with RAYTRACER/raypipe_simple_caches.sv), every unit stepped once a
// cycle with the RTL's valid/stall handshake, written from the RTL apart from any timed model, as
// rtl_cycle_model is for the thesis RTU. docs/raypipe.md, "Timing rules (the per-cycle
// reference)", gives the rules unit by unit with their R1 files, and what is not modelled yet.
// Beside the final build: two traversal units (raypipe.traversal_units = 2, R1's earlier
// raypipe_2trav.sv) and the designed set-associative caches in front of DRAM (raypipe.cache =
// set_associative, raypipe_cache.h).
//
// The arithmetic and the traversal's decisions are kinds/kd's (kd_units.h over the memory image of
// kd_image.h, read as kd_traversal.h reads it), so each ray's result is bit-exact with the golden
// traversal; the control (short stack, restart, list unit, routing) is transcribed here from the
// RTL. Input: the primary rays in the PRG's issue order with their pixel ids (the PRG's values and
// pixel order are raypipe/'s); the PRG's timing is modelled here.
//
// Cycle 0 is the first cycle the PRG is active (a v0 cycle of the shared modulo-3 phase: v0 when
// cycle % 3 == 0, v1 at 1, v2 at 2, as t5.sv's counter). By default the shader's ray-id FIFO is
// full at cycle 0 (reset long past; RaypipeCycleOptions::cyclesSinceReset models the fill).

#include <vector>

#include "kinds/kd/kd_image.h"
#include "raypipe/raypipe_config.h"
#include "raypipe/raypipe_run.h"

namespace rtu {

// Runs one frame. Throws std::invalid_argument for a configuration the reference does not take
// (one RaypipeConfig::validate refuses, a negative VGA phase), logic_error
// when the pipe breaks one of its own rules (a write to a full FIFO, a ray id used twice, a hazard
// on a ray's stack or restart record, no progress for a million cycles).
RaypipeCycleRun runRaypipeCycles(const RaypipeConfig& config, const KdImage& image,
                                 const std::vector<RaypipeCycleRay>& rays,
                                 const RaypipeCycleOptions& options = {});

}  // namespace rtu
