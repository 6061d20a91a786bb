#pragma once
// The kd kind's frame outputs (app/kind_outputs.h): seed 001's k-d tree's results as the triangle
// kinds' pixels (app/triangle_render.h) and its counters per ray.

#include "app/kind_outputs.h"
#include "app/triangle_render.h"
#include "kinds/kd/kd_counters.h"
#include "kinds/kd/kd_kind.h"

namespace rtu {

template <>
struct KindOutputs<KdKind> {
  static std::string core(const RunConfig& settings);
  class Tally {
   public:
    Tally(const RunConfig& settings, const FrameScene& scene);
    void add(const CoreKindResult& result, PixelSink* frame);
    std::string describe() const;

   private:
    TriangleResults<KdKind, KdCounters> results_;
  };
};

}  // namespace rtu
