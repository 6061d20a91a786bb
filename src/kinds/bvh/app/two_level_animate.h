#pragma once
// `rtusim animate --core bvh` (docs/scenes.md, "On the BVH core"): the animated scene file's frames
// on the two-level BVH (kinds/bvh/explore/two_level_animation.h), each written as an image and a
// row of the per-frame CSV, with a line per frame: the top level's build time, nodes and SAH, the
// frame's cycles and frame rate.

#include <functional>
#include <string>
#include <vector>

#include "config/run_config.h"
#include "run/model_run.h"
#include "scene/scene_file.h"

namespace rtu {

struct TwoLevelAnimateRequest {
  const SceneDescription* scene = nullptr;
  const RunConfig* settings = nullptr;  // its rtu (core bvh) and accel (the meshes' builder)
  ModelKind model = ModelKind::Golden;
  std::string csvPath;
  std::function<std::string(int frame)> framePath;
};

// The frames' image paths, in order.
std::vector<std::string> animateTwoLevel(const TwoLevelAnimateRequest& request);

}  // namespace rtu
