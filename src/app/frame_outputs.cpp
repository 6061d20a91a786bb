#include "app/frame_outputs.h"

#include "app/triangle_render.h"
#include "kinds/core_result.h"
#include "kinds/svo/result_summary.h"

namespace rtu {
namespace {

// A registered kind's outputs: core, results and pixels (a kind without them does not compile).
template <class Kind>
struct FrameOutputsOf;

template <>
struct FrameOutputsOf<SvoKind> {
  static std::string core(const RunConfig& settings) {
    const GoldenConfig& golden = settings.rtu.coreConfig<SvoKind>();
    return golden.format.describe() + ", " + toString(golden.conversion) + " conversion, " +
           std::to_string(golden.stackFrames) + " stack frames";
  }
  static std::string results(const RunConfig&, const std::vector<CoreKindResult>& results) {
    return ResultSummary::of(svoResults(results)).describe();
  }
  static RenderedFrame pixels(const RunConfig& settings, const FrameScene&,
                              const std::vector<CoreKindResult>& results) {
    return RenderedFrame::fromResults(settings.camera, settings.rtu.coreConfig<SvoKind>().format,
                                      svoResults(results));
  }
};

template <>
struct FrameOutputsOf<BvhKind<>> {
  static std::string core(const RunConfig& settings) {
    const BvhConfig& core = settings.rtu.coreConfig<BvhKind<>>();
    return "bvh core, " + toString(core.triangleTest) + " test, " +
           std::to_string(core.stackDepth) + " stack entries";
  }
  static std::string results(const RunConfig&, const std::vector<CoreKindResult>& results) {
    return describeBvhResults(resultsOfKind<BvhKind<>>(results));
  }
  static RenderedFrame pixels(const RunConfig& settings, const FrameScene& scene,
                              const std::vector<CoreKindResult>& results) {
    return triangleFrame(settings.camera, scene, resultsOfKind<BvhKind<>>(results));
  }
};

template <>
struct FrameOutputsOf<BihKind<>> {
  static std::string core(const RunConfig& settings) {
    const BihConfig& core = settings.rtu.coreConfig<BihKind<>>();
    return "bih core, " + bihFormatName(core.format) + " fixed-point formats, triangle unit " +
           std::to_string(core.cycles.triangleLatency) + " cycles";
  }
  static std::string results(const RunConfig& settings,
                             const std::vector<CoreKindResult>& results) {
    return describeBihResults(resultsOfKind<BihKind<>>(results),
                              settings.rtu.coreConfig<BihKind<>>().cycles.triangleInterval);
  }
  static RenderedFrame pixels(const RunConfig& settings, const FrameScene& scene,
                              const std::vector<CoreKindResult>& results) {
    return triangleFrame(settings.camera, scene, resultsOfKind<BihKind<>>(results));
  }
};

template <>
struct FrameOutputsOf<KdKind> {
  static std::string core(const RunConfig& settings) {
    const KdTraversalConfig& core = settings.rtu.coreConfig<KdKind>();
    return "kd core, " + std::to_string(core.stackDepth) + "-entry short stack, triangle unit " +
           std::to_string(core.cycles.triangleLatency) + " cycles";
  }
  static std::string results(const RunConfig&, const std::vector<CoreKindResult>& results) {
    return describeKdResults(resultsOfKind<KdKind>(results));
  }
  static RenderedFrame pixels(const RunConfig& settings, const FrameScene& scene,
                              const std::vector<CoreKindResult>& results) {
    return triangleFrame(settings.camera, scene, resultsOfKind<KdKind>(results));
  }
};

}  // namespace

std::string describeCore(const RunConfig& settings) {
  return withCoreKind(settings.rtu.core,
                      [&](auto kind) { return FrameOutputsOf<decltype(kind)>::core(settings); });
}

std::string describeResults(const RunConfig& settings, const std::vector<CoreKindResult>& results) {
  return withCoreKind(settings.rtu.core, [&](auto kind) {
    return FrameOutputsOf<decltype(kind)>::results(settings, results);
  });
}

RenderedFrame framePixels(const RunConfig& settings, const FrameScene& scene,
                          const std::vector<CoreKindResult>& results) {
  return withCoreKind(settings.rtu.core, [&](auto kind) {
    return FrameOutputsOf<decltype(kind)>::pixels(settings, scene, results);
  });
}

}  // namespace rtu
