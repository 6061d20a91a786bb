#include "app/frame_outputs.h"

#include "app/kind_outputs.h"
#include "kind_app_plugins.h"

namespace rtu {
namespace {

// The pixels of `results` placed into `frame` by the kind's tally (KindOutputs<Kind>::Tally).
template <class Kind>
void placePixels(const RunConfig& settings, const FrameScene& scene,
                 const std::vector<CoreKindResult>& results, RenderedFrame& frame) {
  typename KindOutputs<Kind>::Tally tally(settings, scene);
  for (const CoreKindResult& result : results) tally.add(result, &frame);
}

}  // namespace

std::string describeCore(const RunConfig& settings) {
  return withCoreKind(settings.rtu.core,
                      [&](auto kind) { return KindOutputs<decltype(kind)>::core(settings); });
}

RenderedFrame framePixels(const RunConfig& settings, const FrameScene& scene,
                          const std::vector<CoreKindResult>& results) {
  RenderedFrame frame(settings.camera);
  withCoreKind(settings.rtu.core,
               [&](auto kind) { placePixels<decltype(kind)>(settings, scene, results, frame); });
  return frame;
}

}  // namespace rtu
