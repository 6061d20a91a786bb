#pragma once
// The BVH kind's own outputs of a rendered frame (issue 28): its pixels and its report lines, from
// the results of a frame on the scene frame_scene.h built for it (`render --core bvh`).

#include <string>
#include <vector>

#include "app/frame_images.h"
#include "explore/frame_scene.h"
#include "kinds/bvh/bvh_kind.h"

namespace rtu {

// The frame's pixels from results whose id words are pixel indices; the normal of each hit
// triangle in the world.
RenderedFrame bvhFrame(const Camera& camera, const FrameScene& scene,
                       const std::vector<BvhResult>& results);

// Hits, mean cost and the BVH counters of a frame's results, as report lines.
std::string describeBvhResults(const std::vector<BvhResult>& results);

}  // namespace rtu
