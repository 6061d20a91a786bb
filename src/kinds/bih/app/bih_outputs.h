#pragma once
// The bih kind's frame outputs (app/kind_outputs.h): seed 004's BIH's results as the triangle
// kinds' pixels (app/triangle_render.h) and its counters per ray.

#include "app/kind_outputs.h"
#include "kinds/bih/bih_kind.h"

namespace rtu {

template <>
struct KindOutputs<BihKind<>> {
  static std::string core(const RunConfig& settings);
  static std::string results(const RunConfig& settings, const std::vector<CoreKindResult>& results);
  static RenderedFrame pixels(const RunConfig& settings, const FrameScene& scene,
                              const std::vector<CoreKindResult>& results);
};

}  // namespace rtu
