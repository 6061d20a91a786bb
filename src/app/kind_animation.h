#pragma once
// A core kind's own way through `rtusim animate`, beside the SVO scene manager's (which merges the
// models' octrees per ray in command_animate.cpp). A kind plugs in by specialising
// KindAnimation<Kind> in its own folder, kinds/<kind>/app/ (included as "kind_app_plugins.h"),
// with:
//   kAnimates            true;
//   refuse(options)      throws std::invalid_argument for an animate option it has no use for;
//   run(request)         renders every frame (images, the per-frame CSV, a line per frame) and
//                        returns the images' paths in frame order;
//   listStatistics(out)  its per-frame CSV columns, for `rtusim stats --list`.
// A kind without a specialisation does not animate: `animate --core KIND` is refused naming it.
// The BVH's is the two-level BVH rebuilt per frame (kinds/bvh/app/bvh_animation.h).

#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "config/run_config.h"
#include "run/model_run.h"
#include "scene/scene_file.h"

namespace rtu {

// What animate hands a kind: the scene file, the resolved settings and where the outputs go.
struct AnimationRequest {
  const SceneDescription* scene = nullptr;
  const RunConfig* settings = nullptr;
  ModelKind model = ModelKind::Golden;
  std::string csvPath;
  std::function<std::string(int frame)> framePath;
  int threads = 1;  // --threads, or its default (the host's cores)
};

// The animate options a kind may refuse.
struct AnimationOptionsUsed {
  bool noHitBuffer = false, traceAll = false, workers = false;
  int threads = 0;  // --threads as given; 0: not given
  ModelKind model = ModelKind::Golden;
};

template <class Kind>
struct KindAnimation {
  static constexpr bool kAnimates = false;
};

}  // namespace rtu
