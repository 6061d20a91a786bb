#include "kinds/svo/explore/svo_scene.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "kinds/svo/golden_model.h"
#include "kinds/svo/ray_setup.h"
#include "kinds/svo/scene_loader.h"
#include "kinds/svo/stack_check.h"
#include "kinds/svo/svo_validator.h"

namespace rtu {

FrameScene KindScene<SvoKind>::load(const RunConfig& settings) {
  // A deep build takes minutes: refused before it.
  checkBuiltSceneFitsStack(settings.scene, settings.rtu.coreConfig<SvoKind>().stackFrames,
                           settings.allowStackOverflow);
  Scene built = loadScene(settings.scene);
  FrameScene scene;
  scene.stackNeeded = descriptorDepths(built.image, {built.image.root}).front();
  scene.words = std::move(built.image.words);
  scene.entry = built.image.root;
  scene.name = std::move(built.name);
  scene.description = std::move(built.summary);
  return scene;
}

std::vector<HostRecord> KindScene<SvoKind>::records(const FrameScene& scene,
                                                    const RunConfig& settings) {
  checkNeededFrames({scene.entry}, {scene.stackNeeded},
                    settings.rtu.coreConfig<SvoKind>().stackFrames, settings.allowStackOverflow,
                    sceneSource(settings.scene));
  return frameRecordsOf<KindScene<SvoKind>>(scene, settings);
}

HostRecord KindScene<SvoKind>::record(const FrameScene& scene, const RunConfig& settings,
                                      uint32_t id, const Ray& ray) {
  return makeTValueRecord(id, ray, scene.entry, settings.epsilon);
}

PassSource KindScene<SvoKind>::passSource(const FrameScene& scene, const RunConfig& settings) {
  const GoldenConfig& golden = settings.rtu.coreConfig<SvoKind>();
  golden.validate();
  PassSource source;
  source.words = scene.words;
  source.box = makeModelHeader(ModelPlacement{}, scene.entry);
  const ModelHeaderWords header = encodeModelHeader(source.box);
  source.modelAddress = static_cast<uint32_t>(source.words.size());
  source.words.insert(source.words.end(), header.begin(), header.end());
  const WordMemory memory(source.words);
  GoldenModel model(memory, golden);
  // The frame's rays a block at a time: only the hits are held, not a record or result per pixel.
  constexpr uint64_t kBlock = 1 << 16;
  settings.camera.validate();
  const uint64_t pixels = settings.camera.pixelCount();
  std::vector<RayRecord> block;
  for (uint64_t first = 0; first < pixels; first += kBlock) {
    block.clear();
    for (uint64_t id = first; id < std::min(pixels, first + kBlock); ++id)
      block.push_back(makeRayRecord(static_cast<uint32_t>(id), settings.camera.pixelRay(id),
                                    source.modelAddress));
    const std::vector<SurfaceHit> hits =
        surfaceHits(block, model.traceRays(block, golden.epsilon), source.box, golden.format);
    source.hits.insert(source.hits.end(), hits.begin(), hits.end());
  }
  source.selfOffset = std::ldexp(16.0, -golden.format.fractionBits);
  return source;
}

}  // namespace rtu
