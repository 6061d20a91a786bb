#pragma once
// The bih kind's frame outputs (app/kind_outputs.h): seed 004's BIH's results as the triangle
// kinds' pixels (app/triangle_render.h) and its counters per ray.

#include "app/kind_outputs.h"
#include "app/triangle_render.h"
#include "kinds/bih/bih_counters.h"
#include "kinds/bih/bih_kind.h"

namespace rtu {

template <>
struct KindOutputs<BihKind<>> {
  static std::string core(const RunConfig& settings);
  class Tally {
   public:
    Tally(const RunConfig& settings, const FrameScene& scene);
    void add(const CoreKindResult& result, PixelSink* frame);
    std::string describe() const;

   private:
    uint32_t unitInterval_;
    TriangleResults<BihKind<>, BihCounters> results_;
  };
};

}  // namespace rtu
