#pragma once
// Each core kind's own outputs of a rendered frame (`render`): the line naming its core, the report
// of its results and the frame's pixels, chosen by the run's kind (`core`). The SVO kind's are the
// thesis' (RenderedFrame::fromResults, ResultSummary); the triangle kinds' are in
// app/triangle_render.h. A new kind specialises FrameOutputsOf (frame_outputs.cpp).

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
