#pragma once
// The frames of an animation in forked worker processes (sweep_workers.h): contiguous ranges of
// frames, each on a renderer of its own in a worker, several ranges per worker so that a worker
// with cheap frames (a still camera, most rays saved) takes the next range. A range that does
// not start at frame 0 first primes its renderer with the frame before
// (AnimationRenderer::prime), so the hit buffer saves the same rays as in one process: every
// frame's statistics and image are the same whatever the number of workers.

#include <functional>
#include <vector>

#include "explore/animation_run.h"

namespace rtu {

struct FrameRange {
  int first = 0;
  int end = 0;  // one past the last frame
};
// Frames 0 .. frames - 1 in min(ranges, frames) ranges whose lengths differ by one at most.
std::vector<FrameRange> splitFrames(int frames, int ranges);

// Ranges per worker: each costs one primed frame, traced on the golden model.
constexpr int kFrameRangesPerWorker = 4;

// Renders every frame of `scene` in up to `workers` workers (one: a single range). In a worker
// `writeFrame` writes a rendered frame's files; in the parent `frameDone` gets each frame's
// statistics in frame order, and a progress line with ETA counts the frames. Throws
// std::runtime_error naming the frames of a worker that failed, after the other workers finished.
void renderFramesInWorkers(const SceneDescription& scene, const std::vector<SceneModel>& models,
                           const AnimationOptions& options, int workers,
                           const std::function<void(const SceneFrame&)>& writeFrame,
                           const std::function<void(const FrameStatistics&)>& frameDone);

}  // namespace rtu
