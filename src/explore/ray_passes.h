#pragma once
// A frame of passes (issue 32, `render --passes primary,shadow,ao`): the camera's primary rays,
// then secondary rays spawned from their hits (inputs/ray_workload.h), each pass a workload of its
// own, run on the chosen model after the one before as a renderer's passes follow each other: its
// own statistics, and the frame's cycles the passes' sum. The SVO kind's: the secondary passes'
// ray records point at a model header appended after the octree, placing its cube where the
// frame's t-value records see it (the identity).

#include <optional>
#include <string>
#include <vector>

#include "config/run_config.h"
#include "explore/frame_scene.h"
#include "inputs/ray_workload.h"
#include "run/rtu_simulation.h"

namespace rtu {

struct PassRun {
  RayType type = RayType::Primary;
  uint32_t raysPerHit = 1;               // ids: pixel * raysPerHit + light or sample
  std::vector<RayRecord> rays;           // in the order they ran
  std::vector<TraversalResult> results;  // the same order
  std::optional<RtuRun> run;             // on a timed model: its statistics
};

// One pass's figures in a row of a frame with passes (fps, sweep, compare: the row's
// statistics.passes.<pass>, and the CSV's <pass>_rays and <pass>_cycles_per_ray).
struct FramePass {
  RtuStatistics statistics;  // the pass's run
  static const StatisticGroup<FramePass>& declaration();
};

// The secondary rays' settings of a run (the workload.* keys), with the self-intersection offset
// 16 steps of the SVO format (its golden t is within a few steps of the exact one). Throws
// std::invalid_argument naming a setting that is not valid.
RayWorkloadSpec passSpec(const RunConfig& settings);

// Every pass of `passes` after the first (the caller's primary frame) on `scene` (an SVO scene),
// on the model `settings` choose, with the rays of passSpec(settings).
std::vector<PassRun> runSecondaryPasses(const FrameScene& scene, const RunConfig& settings,
                                        const std::vector<RayType>& passes);

// Per pixel of a frame of `pixels`: the share of a pass's rays from that pixel's hit that reached
// their end without a hit (a light seen, an AO direction open); a shadow ray not spawned (the light
// behind the face) counts as blocked. Pixels without rays get 1.
std::vector<double> openShare(const PassRun& pass, size_t pixels);

}  // namespace rtu
