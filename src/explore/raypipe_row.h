#pragma once
// A row of fps or sweep with architecture = raypipe (issue 29): the frame of seed 001's ray pipe
// (raypipe_frame.h) on its timed model, which is exact (cycle for cycle its per-cycle reference),
// so every row is answered by it; the row is the run's JSON with the pipe's statistics
// (raypipe/raypipe_statistics.h), the same a `render --architecture raypipe --stats` writes.

#include <nlohmann/json.hpp>

#include "config/configuration.h"
#include "explore/frame_scene.h"

namespace rtu {

// Throws std::invalid_argument when the pipe's timed frame cannot run whatever the scene: settings
// the pipe or its timed model refuse, the frame's camera, a recorded workload (jobs, rays).
void checkRaypipeFrameRuns(const RunConfig& settings);

// Throws std::invalid_argument when a row of the pipe cannot run whatever the scene: as
// checkRaypipeFrameRuns, and a model other than ca (golden has no cycles, and the pipe has no
// loosely-timed form) or a sample.
void validateRaypipeRow(const RunConfig& settings);

// The run JSON with "status": "ok" of the frame on `scene` (loadFrameScene's for the pipe).
nlohmann::ordered_json runRaypipeRow(const Configuration& configuration, const FrameScene& scene);

}  // namespace rtu
