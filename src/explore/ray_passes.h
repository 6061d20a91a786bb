#pragma once
// A frame of passes (issue 32, `render --passes primary,shadow,ao`): the camera's primary rays,
// then secondary rays spawned from their hits (inputs/ray_workload.h), the passes one workload
// (one job stream, in pass order) with each pass's statistics its window of that run. Every core
// kind's: each spawns from its own golden hits, its records and offsets its KindScene's
// (explore/kind_scene.h).

#include <optional>
#include <string>
#include <vector>

#include "config/run_config.h"
#include "explore/frame_scene.h"
#include "explore/kind_scene.h"
#include "inputs/ray_workload.h"
#include "run/rtu_simulation.h"

namespace rtu {

struct PassRun {
  RayType type = RayType::Primary;
  uint32_t raysPerHit = 1;      // ids: pixel * raysPerHit + light or sample
  std::vector<RayRecord> rays;  // in the order they ran
  std::vector<bool> hits;       // whether each met something, the same order
  // On a timed model: the pass's part of the frame's run (its window: run/statistics_window.h).
  std::optional<RtuStatistics> statistics;
};

// A frame's secondary passes run as one workload behind its primary rays.
struct FramePassesRun {
  std::vector<PassRun> passes;         // each pass after the primary, in order
  std::optional<RtuStatistics> frame;  // on a timed model: the run of every pass's rays
};

// One pass's figures in a row of a frame with passes (fps, sweep, compare: the row's
// statistics.passes.<pass>, and the CSV's <pass>_rays and <pass>_cycles_per_ray).
struct FramePass {
  RtuStatistics statistics;  // the pass's run
  static const StatisticGroup<FramePass>& declaration();
};

// The secondary rays' settings of a run (the workload.* keys). Throws std::invalid_argument naming
// a setting that is not valid.
RayWorkloadSpec passSpec(const RunConfig& settings);

// The most rays the passes of `settings` after the primary one hold for a frame of `pixels` (each
// pixel a hit; random rays as many as workload.random_rays says): what a frame of passes holds
// beside its pixels and their hits (app/frame_stream.h's estimate).
double passRays(const RunConfig& settings, size_t pixels);

// Where the secondary passes of the camera's frame on `scene` spawn, by its kind
// (KindScene<Kind>::passSource: its golden hits, memory, model header and offsets).
PassSource framePassSource(const FrameScene& scene, const RunConfig& settings);

// The passes of `passes` after the first on the camera's frame on `scene`, of any core kind, their
// rays (passSpec(settings)) spawned from the kind's own golden hits with its offsets. On a timed
// model (`settings.model`) the frame is one workload: the primary records, then each pass's rays,
// submitted in that order as one job stream and run once; each pass's statistics are its window
// of that run: the run of the passes up to it less the run of those before it (the same stream
// cut after the earlier pass), `primary` being the run of the primary records alone (the caller's
// frame). So the primary's statistics and the passes' sum to the frame's, counter for counter.
// On the golden model the passes are traced untimed (no statistics).
FramePassesRun runFramePasses(const FrameScene& scene, const RunConfig& settings,
                              const std::vector<RayType>& passes,
                              const std::optional<RtuStatistics>& primary);

// Per pixel of a frame of `pixels`: the share of a pass's rays from that pixel's hit that reached
// their end without a hit (a light seen, an AO direction open); a shadow ray not spawned (the light
// behind the face) counts as blocked. Pixels without rays get 1.
std::vector<double> openShare(const PassRun& pass, size_t pixels);

}  // namespace rtu
