#pragma once
// Each core kind's own outputs of a rendered frame (frame_outputs.h chooses the kind once,
// withCoreKind). A kind plugs in by specialising KindOutputs<Kind> in its own folder,
// kinds/<kind>/app/ (cmake/KindPlugins.cmake includes every header there as
// "kind_app_plugins.h"), with:
//   core      the line naming its core and settings ("bvh core, float32 test, 32 stack entries");
//   Tally     a frame's results taken one at a time, as they leave a run (app/frame_stream.h) or
//             from a vector (frame_outputs.h): constructed from the run's settings and scene
//             (both outlive it), `add(result, frame)` counts a result and, given a frame, places
//             its pixel; `describe()` is the report lines of the results added (hits, costs, the
//             kind's counters).
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
