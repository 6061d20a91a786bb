#include "kinds/svo/app/svo_outputs.h"

#include "kinds/core_result.h"

namespace rtu {

std::string KindOutputs<SvoKind>::core(const RunConfig& settings) {
  const GoldenConfig& golden = settings.rtu.coreConfig<SvoKind>();
  return golden.format.describe() + ", " + toString(golden.conversion) + " conversion, " +
         std::to_string(golden.stackFrames) + " stack frames";
}

KindOutputs<SvoKind>::Tally::Tally(const RunConfig& settings, const FrameScene&)
    : format_(settings.rtu.coreConfig<SvoKind>().format) {}

// The thesis' report (ResultSummary) and pixels (svoPixel).
void KindOutputs<SvoKind>::Tally::add(const CoreKindResult& result, PixelSink* frame) {
  const TraversalResult& own = svoResult(result);
  summary_.add(own);
  if (frame) frame->place(own.id(), svoPixel(format_, own));
}

std::string KindOutputs<SvoKind>::Tally::describe() const { return summary_.describe(); }

}  // namespace rtu
