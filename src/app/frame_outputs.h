#pragma once
// Each core kind's own outputs of a rendered frame (`render`): the line naming its core, the report
// of its results and the frame's pixels, chosen by the run's kind (`core`): each kind's
// KindOutputs (app/kind_outputs.h), in its folder kinds/<kind>/app/.

#include <string>
#include <vector>

#include "app/frame_images.h"
#include "config/run_config.h"
#include "explore/frame_scene.h"

namespace rtu {

// "Q16.16, round conversion, 12 stack frames"; "bvh core, float32 test, 32 stack entries".
std::string describeCore(const RunConfig& settings);
// Report lines of a frame's results (hits, costs, the kind's counters).
std::string describeResults(const RunConfig& settings, const std::vector<CoreKindResult>& results);
// The frame's pixels from results in pixel order.
RenderedFrame framePixels(const RunConfig& settings, const FrameScene& scene,
                          const std::vector<CoreKindResult>& results);

}  // namespace rtu
