#pragma once
// `rtusim fidelity --architecture raypipe` (issue 29): seed 001's ray pipe has one timed model and
// it is exact, so its fidelity study is the check a user can run on any frame that it is: the
// frame on the per-cycle reference (reference/raypipe_cycles.h, the baseline), on the timed model
// (sim/raypipe/raypipe_timed.h) and on the golden traversal (raypipe/raypipe_golden.h), with each
// mode's host time and speed-up over the reference, its frame cycles and their error, the per-ray
// error of each ray's cycles in the pipe (exit - issue), and whether its results equal golden's.
// The pipe has no loosely-timed or sampled mode: its timed model costs per ray already.

#include <vector>

#include "config/run_config.h"
#include "explore/frame_scene.h"
#include "run/fidelity_study.h"

namespace rtu {

// The modes "reference", "raypipe" (the timed model) and "golden", in that order, on the frame
// `settings` describe over `scene` (loadFrameScene's for the pipe).
std::vector<ModeFidelity> measureRaypipeFidelity(const RunConfig& settings,
                                                 const FrameScene& scene);

// Whether every mode of such a study agrees with the reference and golden: the frame cycles, every
// ray's cycles and every result equal.
bool raypipeModesAgree(const std::vector<ModeFidelity>& modes);

}  // namespace rtu
