#include "kinds/bvh/app/bvh_animation.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "app/frame_images.h"
#include "app/scene_shading.h"
#include "base/output_file.h"
#include "explore/exploration_run.h"
#include "kinds/bvh/explore/two_level_animation.h"
#include "run/statistics_output.h"
#include "sim/rtu_resources.h"

namespace rtu {
namespace {

std::vector<float> shade(const TwoLevelAnimation& animation, const TwoLevelFrame& frame,
                         const SceneDescription& scene) {
  std::vector<float> rgb;
  rgb.reserve(frame.results.size() * 3);
  for (size_t i = 0; i < frame.results.size(); ++i) {
    const BvhResult& hit = frame.results[i];
    const int x = static_cast<int>(i % scene.width), y = static_cast<int>(i / scene.width);
    glm::dvec3 colour = sceneSky(frame.camera.primaryRay(x, y).direction);
    if (hit.hit)
      colour = shadeSceneSurface(scene.instances.at(animation.instanceOf(hit.primitive)).colour,
                                 animation.worldNormal(frame, x, y, hit));
    for (int k = 0; k < 3; ++k) rgb.push_back(static_cast<float>(std::clamp(colour[k], 0.0, 1.0)));
  }
  return rgb;
}

void printFrame(const TwoLevelFrameStatistics& f) {
  std::printf("frame %4d  top level %llu instances, %llu nodes, SAH %.3f (seed %.3f), built in "
              "%.1f us; %llu cycles, %.3f ms, %.1f frames/s\n",
              f.frame, static_cast<unsigned long long>(f.instances),
              static_cast<unsigned long long>(f.topNodes), f.topSah, f.topSahSeed,
              f.topBuildSeconds * 1e6, static_cast<unsigned long long>(f.cycles), f.frameMs(),
              f.framesPerSecond());
}

void printSummary(const std::vector<TwoLevelFrameStatistics>& frames, double seconds) {
  double build = 0, buildMax = 0, cycles = 0, perRay = 0;
  for (const TwoLevelFrameStatistics& f : frames) {
    build += f.topBuildSeconds;
    buildMax = std::max(buildMax, f.topBuildSeconds);
    cycles += static_cast<double>(f.cycles);
    perRay += f.instancesPerRay();
  }
  const double n = static_cast<double>(frames.size()), clock = frames.front().clockMhz;
  std::printf("top level   %.1f us mean build per frame (max %.1f us)\n", 1e6 * build / n,
              1e6 * buildMax);
  std::printf("frames      %zu, %.3f ms mean frame time at %.0f MHz (%.1f frames/s); %.2f "
              "instances entered per ray\n",
              frames.size(), cycles / n / (clock * 1e3), clock,
              cycles > 0 ? clock * 1e6 * n / cycles : 0.0, perRay / n);
  std::printf("host        %.2f s\n", seconds);
}

// The RTU's estimate with two-level cores (kinds/bvh/bvh_resources.h), the scene on chip with
// ideal memory; the transform units' share against one-level cores.
void printResources(const RtuConfig& rtu, uint64_t imageWords) {
  const ResourceEstimate estimate =
      rtuResources(rtu, imageWords, twoLevelCoreResources(rtu.coreConfig<BvhKind<>>()));
  const ResourceEstimate oneLevel = rtuResources(rtu, imageWords);
  std::printf("resources   %lld DSP48E (%lld in the cores' transform units), %lld 18 Kbit block "
              "RAMs, %lld LUTs of arithmetic (docs/comparison.md)\n",
              static_cast<long long>(estimate.dsp48e()),
              static_cast<long long>(estimate.dsp48e() - oneLevel.dsp48e()),
              static_cast<long long>(estimate.blockRams()),
              static_cast<long long>(estimate.luts()));
}

}  // namespace

void KindAnimation<BvhKind<>>::refuse(const AnimationOptionsUsed& options) {
  if (options.noHitBuffer || options.traceAll || options.workers)
    throw std::invalid_argument(
        "animate --core bvh: --no-hit-buffer, --trace-all and --workers are the svo scene "
        "manager's; the two-level BVH traces every pixel in one process");
  if (options.threads > 1 && options.model != ModelKind::Golden)
    throw std::invalid_argument(std::string("animate --core bvh --model ") +
                                toString(options.model) +
                                ": --threads renders frames in parallel on --model golden only; "
                                "a ca or lt frame is a SystemC simulation, one at a time in a "
                                "process (use --threads 1, or --model golden)");
}

void KindAnimation<BvhKind<>>::listStatistics(std::ostream& out) {
  rtu::listStatistics(out, "# " + TwoLevelFrameStatistics::declaration().title() + " (--core bvh)",
                      TwoLevelFrameStatistics::declaration().statistics());
}

std::vector<std::string> KindAnimation<BvhKind<>>::run(const AnimationRequest& request) {
  const SceneDescription& scene = *request.scene;
  TwoLevelAnimationOptions options;
  options.accel = request.settings->accel;
  options.model = request.model;
  options.rtu = request.settings->rtu;
  const auto start = std::chrono::steady_clock::now();
  TwoLevelAnimation animation(scene, options);
  for (size_t m = 0; m < animation.meshes().size(); ++m)
    std::printf("model       %s: %zu triangles, mesh BVH (%s) built once in %.3f s\n",
                scene.models[m].name.c_str(), animation.meshes()[m].triangles.size(),
                options.accel.builder.c_str(), animation.meshBuildSeconds()[m]);
  OutputFile csvFile(request.csvPath);
  std::ostream& csv = csvFile.stream();
  csv << csvLine(statisticsHeader<TwoLevelFrameStatistics>());
  std::vector<TwoLevelFrameStatistics> frames;
  std::vector<std::string> paths;
  // The golden model renders `threads` frames at a time; the simulations one (refuse() above).
  const int threads = request.model == ModelKind::Golden ? request.threads : 1;
  animation.renderFrames(threads, [&](const TwoLevelFrame& rendered) {
    paths.push_back(request.framePath(rendered.statistics.frame));
    writeRgbImage(paths.back(), scene.width, scene.height, shade(animation, rendered, scene));
    frames.push_back(rendered.statistics);
    csv << csvLine(statisticsFields(rendered.statistics, "%.6g"));
    printFrame(rendered.statistics);
  });
  csvFile.commit();
  printSummary(frames,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  printResources(options.rtu, animation.imageWords());
  return paths;
}

}  // namespace rtu
