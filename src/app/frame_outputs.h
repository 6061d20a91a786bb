#pragma once
// Each core kind's own outputs of a rendered frame: the line naming its core and the frame's pixels
// from a vector of results, chosen by the run's kind (`core`): each kind's KindOutputs
// (app/kind_outputs.h), in its folder kinds/<kind>/app/.

#include <string>
#include <vector>

#include "app/frame_images.h"
#include "config/run_config.h"
#include "explore/frame_scene.h"

namespace rtu {

// "Q16.16, round conversion, 12 stack frames"; "bvh core, float32 test, 32 stack entries".
std::string describeCore(const RunConfig& settings);
// The frame's pixels from a run's results (a frame streamed as it runs takes them one at a time:
// app/frame_stream.h).
RenderedFrame framePixels(const RunConfig& settings, const FrameScene& scene,
                          const std::vector<CoreKindResult>& results);

}  // namespace rtu
