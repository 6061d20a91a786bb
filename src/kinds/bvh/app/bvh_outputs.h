#pragma once
// The bvh kind's frame outputs (app/kind_outputs.h): seed 003's BVH's results as the triangle
// kinds' pixels (app/triangle_render.h) and its counters per ray.

#include "app/kind_outputs.h"
#include "kinds/bvh/bvh_kind.h"

namespace rtu {

template <>
struct KindOutputs<BvhKind<>> {
  static std::string core(const RunConfig& settings);
  static std::string results(const RunConfig& settings, const std::vector<CoreKindResult>& results);
  static RenderedFrame pixels(const RunConfig& settings, const FrameScene& scene,
                              const std::vector<CoreKindResult>& results);
};

}  // namespace rtu
