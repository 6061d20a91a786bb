#pragma once
// `rtusim animate --core bvh` (app/kind_animation.h; docs/scenes.md, "On the BVH core"): the
// animated scene file's frames on the two-level BVH (kinds/bvh/explore/two_level_animation.h),
// each written as an image and a row of the per-frame CSV, with a line per frame: the top level's
// build time, nodes and SAH, the frame's cycles and frame rate.

#include <ostream>
#include <string>
#include <vector>

#include "app/kind_animation.h"
#include "kinds/bvh/bvh_kind.h"

namespace rtu {

template <>
struct KindAnimation<BvhKind<>> {
  static constexpr bool kAnimates = true;
  // The SVO scene manager's options, which the two-level BVH has none of.
  static void refuse(const AnimationOptionsUsed& options);
  static std::vector<std::string> run(const AnimationRequest& request);
  static void listStatistics(std::ostream& out);
};

}  // namespace rtu
