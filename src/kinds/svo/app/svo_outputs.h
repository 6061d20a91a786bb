#pragma once
// The SVO kind's frame outputs (app/kind_outputs.h): the thesis' (RenderedFrame::fromResults,
// ResultSummary).

#include "app/kind_outputs.h"
#include "kinds/svo/result_summary.h"
#include "kinds/svo/svo_kind.h"

namespace rtu {

template <>
struct KindOutputs<SvoKind> {
  static std::string core(const RunConfig& settings);
  class Tally {
   public:
    Tally(const RunConfig& settings, const FrameScene& scene);
    void add(const CoreKindResult& result, PixelSink* frame);
    std::string describe() const;

   private:
    FixedFormat format_;
    ResultSummary summary_;
  };
};

}  // namespace rtu
