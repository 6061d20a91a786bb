#pragma once
// Each core kind's own outputs of a rendered frame (frame_outputs.h chooses the kind once,
// withCoreKind). A kind plugs in by specialising KindOutputs<Kind> in its own folder,
// kinds/<kind>/app/ (cmake/KindPlugins.cmake includes every header there as
// "kind_app_plugins.h"), with:
//   core      the line naming its core and settings ("bvh core, float32 test, 32 stack entries");
//   results   the report lines of a frame's results (hits, costs, the kind's counters);
//   pixels    the frame's pixels from results in pixel order.
// The triangle kinds' share app/triangle_render.h.

#include <string>
#include <vector>

#include "app/frame_images.h"
#include "config/run_config.h"
#include "explore/frame_scene.h"

namespace rtu {

template <class Kind>
struct KindOutputs;

}  // namespace rtu
