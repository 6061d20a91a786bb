#include "app/frame_outputs.h"

#include "app/kind_outputs.h"
#include "kind_app_plugins.h"

namespace rtu {

std::string describeCore(const RunConfig& settings) {
  return withCoreKind(settings.rtu.core,
                      [&](auto kind) { return KindOutputs<decltype(kind)>::core(settings); });
}

std::string describeResults(const RunConfig& settings, const std::vector<CoreKindResult>& results) {
  return withCoreKind(settings.rtu.core, [&](auto kind) {
    return KindOutputs<decltype(kind)>::results(settings, results);
  });
}

RenderedFrame framePixels(const RunConfig& settings, const FrameScene& scene,
                          const std::vector<CoreKindResult>& results) {
  return withCoreKind(settings.rtu.core, [&](auto kind) {
    return KindOutputs<decltype(kind)>::pixels(settings, scene, results);
  });
}

}  // namespace rtu
