#pragma once
// The bvh kind's frame outputs (app/kind_outputs.h): seed 003's BVH's results as the triangle
// kinds' pixels (app/triangle_render.h) and its counters per ray.

#include "app/kind_outputs.h"
#include "app/triangle_render.h"
#include "kinds/bvh/bvh_counters.h"
#include "kinds/bvh/bvh_kind.h"

namespace rtu {

template <>
struct KindOutputs<BvhKind<>> {
  static std::string core(const RunConfig& settings);
  class Tally {
   public:
    Tally(const RunConfig& settings, const FrameScene& scene);
    void add(const CoreKindResult& result, PixelSink* frame);
    std::string describe() const;

   private:
    TriangleResults<BvhKind<>, BvhCounters> results_;
  };
};

}  // namespace rtu
