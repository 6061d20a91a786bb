#pragma once
// The SVO kind's frame outputs (app/kind_outputs.h): the thesis' (RenderedFrame::fromResults,
// ResultSummary).

#include "app/kind_outputs.h"
#include "kinds/svo/svo_kind.h"

namespace rtu {

template <>
struct KindOutputs<SvoKind> {
  static std::string core(const RunConfig& settings);
  static std::string results(const RunConfig& settings, const std::vector<CoreKindResult>& results);
  static RenderedFrame pixels(const RunConfig& settings, const FrameScene& scene,
                              const std::vector<CoreKindResult>& results);
};

}  // namespace rtu
