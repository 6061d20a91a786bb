#include "kinds/svo/app/svo_outputs.h"

#include "kinds/core_result.h"
#include "kinds/svo/result_summary.h"

namespace rtu {

std::string KindOutputs<SvoKind>::core(const RunConfig& settings) {
  const GoldenConfig& golden = settings.rtu.coreConfig<SvoKind>();
  return golden.format.describe() + ", " + toString(golden.conversion) + " conversion, " +
         std::to_string(golden.stackFrames) + " stack frames";
}

std::string KindOutputs<SvoKind>::results(const RunConfig&,
                                          const std::vector<CoreKindResult>& results) {
  return ResultSummary::of(svoResults(results)).describe();
}

RenderedFrame KindOutputs<SvoKind>::pixels(const RunConfig& settings, const FrameScene&,
                                           const std::vector<CoreKindResult>& results) {
  return RenderedFrame::fromResults(settings.camera, settings.rtu.coreConfig<SvoKind>().format,
                                    svoResults(results));
}

}  // namespace rtu
