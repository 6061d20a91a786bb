#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include "app/bvh_render.h"
#include "app/commands.h"
#include "app/frame_images.h"
#include "app/output_paths.h"
#include "app/run_outputs.h"
#include "app/schema_flags.h"
#include "explore/sweep_workers.h"
#include "kinds/core_result.h"
#include "kinds/svo/golden_model.h"
#include "kinds/svo/result_summary.h"
#include "kinds/svo/stack_check.h"
#include "run/model_run.h"
#include "run/rtu_simulation.h"

namespace rtu {
namespace {

struct RenderOptions {
  RunOutputs outputs;
  std::string image, depthImage, costImage;

  std::vector<NamedPath> imagePaths() const {
    return {{"--image", image}, {"--depth-image", depthImage}, {"--cost-image", costImage}};
  }
  std::vector<NamedPath> outputPaths() const {
    std::vector<NamedPath> paths = outputs.paths();
    const std::vector<NamedPath> images = imagePaths();
    paths.insert(paths.end(), images.begin(), images.end());
    return paths;
  }
  void checkImageFormats() const {
    for (const NamedPath& file : imagePaths())
      if (!file.path.empty()) checkImageFormat(file.option, file.path);
  }
};

// The untimed golden model has no cores, memory, links, statistics or trace: settings of the
// timed model are errors there rather than silently dropped. The loosely-timed model has
// statistics but no trace or timeline.
void checkOutputsOfModel(const RenderOptions& options, const ConfigRequest& request,
                         const Configuration& configuration) {
  const ModelKind model = configuration.values().model;
  if (model == ModelKind::Golden) {
    if (options.outputs.any())
      throw std::invalid_argument(
          "--stats, --trace and --timeline need --model ca or lt: the golden "
          "model is untimed");
    configuration.checkApplicable(request.uses & ~kUseModel, "render --model golden");
  }
  checkOutputsOfModel(options.outputs, model);
}

std::vector<TraversalResult> traceWithGolden(const Scene& scene,
                                             const std::vector<TValueRecord>& jobs,
                                             const Configuration& configuration) {
  GoldenModel model(scene.image.memory(), configuration.values().rtu.coreConfig<SvoKind>());
  const auto start = std::chrono::steady_clock::now();
  std::vector<TraversalResult> results = model.traceAll(jobs);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  char host[128];
  std::snprintf(host, sizeof host, "host        %.3f s, %.2f M rays/s (golden model)\n", seconds,
                results.size() / seconds / 1e6);
  std::cout << ResultSummary::of(results).describe() << host;
  return results;
}

std::vector<TraversalResult> traceWithTimedModel(const Scene& scene,
                                                 const std::vector<TValueRecord>& jobs,
                                                 const Configuration& configuration,
                                                 const RenderOptions& options) {
  const RtuConfig config = options.outputs.traced(configuration.values().rtu);
  checkStackDepth(scene.image, jobs, config.coreConfig<SvoKind>().stackFrames,
                  configuration.values().allowStackOverflow);
  const std::vector<HostRecord> records(jobs.begin(), jobs.end());
  const RtuConfig planned =
      plannedTrace(scene.image.memory(), records, config, options.outputs, std::cout);
  RunProgressLine progress("render", "rays");
  const RtuRun run = runModel(configuration.values().model, scene.image.memory(), records, planned,
                              progress.callback());
  // The frame's images are the SVO kind's outputs.
  std::vector<TraversalResult> results = svoResults(resultsInJobOrder(run));
  std::cout << ResultSummary::of(results).describe();
  reportRun(run, configuration, options.outputs, std::cout);
  if (config.trace) std::cout << "wrote       " << config.trace->path << "\n";
  if (config.timeline.wanted()) std::cout << "wrote       " << config.timeline.path << "\n";
  return results;
}

// The BVH core's frame (app/bvh_render.h) on the chosen model: its results in pixel order.
std::vector<BvhResult> traceBvhFrame(const BvhScene& scene, const std::vector<HostRecord>& records,
                                     const Configuration& configuration,
                                     const RenderOptions& options) {
  const RunConfig& settings = configuration.values();
  const WordMemory memory(scene.words);
  if (settings.model == ModelKind::Golden) {
    const auto start = std::chrono::steady_clock::now();
    const RtuRun run = runModel(ModelKind::Golden, memory, records, settings.rtu);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<BvhResult> results = bvhResults(resultsInJobOrder(run));
    char host[128];
    std::snprintf(host, sizeof host, "host        %.3f s, %.2f M rays/s (golden model)\n", seconds,
                  results.size() / seconds / 1e6);
    std::cout << describeBvhResults(results) << host;
    return results;
  }
  const RtuConfig config = options.outputs.traced(settings.rtu);
  const RtuConfig planned = plannedTrace(memory, records, config, options.outputs, std::cout);
  RunProgressLine progress("render", "rays");
  const RtuRun run = runModel(settings.model, memory, records, planned, progress.callback());
  std::vector<BvhResult> results = bvhResults(resultsInJobOrder(run));
  std::cout << describeBvhResults(results);
  reportRun(run, configuration, options.outputs, std::cout);
  if (config.trace) std::cout << "wrote       " << config.trace->path << "\n";
  if (config.timeline.wanted()) std::cout << "wrote       " << config.timeline.path << "\n";
  return results;
}

// render --core bvh: the scene's triangles as a BVH, the same camera's frame as ray records.
RenderedFrame renderBvh(const Configuration& configuration, const RenderOptions& options) {
  const RunConfig& settings = configuration.values();
  const BvhScene scene = loadBvhScene(settings);
  const std::vector<RayRecord> rays = makeFrameRayRecords(settings.camera, scene.header);
  const BvhConfig& core = settings.rtu.coreConfig<BvhKind<>>();
  std::cout << "scene       " << scene.name << ": " << scene.description << "\n"
            << "model       " << toString(settings.model) << ", bvh core, "
            << toString(core.triangleTest) << " test, " << core.stackDepth << " stack entries\n"
            << "frame       " << settings.camera.width << "x" << settings.camera.height << "\n";
  const std::vector<BvhResult> results = traceBvhFrame(
      scene, std::vector<HostRecord>(rays.begin(), rays.end()), configuration, options);
  return bvhFrame(settings.camera, scene, results);
}

// render on the SVO core: the octree's frame of t-value records.
RenderedFrame renderSvo(const Configuration& configuration, const RenderOptions& options) {
  const RunConfig& settings = configuration.values();
  if (settings.model != ModelKind::Golden)
    checkBuiltSceneFitsStack(settings.scene, settings.rtu.coreConfig<SvoKind>().stackFrames,
                             settings.allowStackOverflow);
  const GoldenConfig golden = settings.rtu.coreConfig<SvoKind>();
  golden.format.validate();
  const Scene scene = loadScene(settings.scene);
  const std::vector<TValueRecord> jobs =
      makeFrameJobs(settings.camera, scene.image.root, settings.epsilon);
  std::cout << "scene       " << scene.name << ": " << scene.summary << "\n"
            << "model       " << toString(settings.model) << ", " << golden.format.describe()
            << ", " << toString(golden.conversion) << " conversion, " << golden.stackFrames
            << " stack frames\n"
            << "frame       " << settings.camera.width << "x" << settings.camera.height << "\n";
  const std::vector<TraversalResult> results =
      settings.model == ModelKind::Golden
          ? traceWithGolden(scene, jobs, configuration)
          : traceWithTimedModel(scene, jobs, configuration, options);
  return RenderedFrame::fromResults(settings.camera, golden.format, results);
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* command = app.add_subcommand(
      "render", "render one frame of primary rays on the cycle-accurate RTU model (or the "
                "loosely-timed or golden model: --model) and report it");
  // The accel settings for the BVH core's build (--builder, --drop-bad-triangles); render
  // builds the structure of its core, so not --accel or the other structures' own.
  auto request = addConfigOptions(
      *command, kUseModel | kUseModelChoice | kUseArithmetic | kUseScene | kUseCamera | kUseAccel,
      {"--accel", "--bih-format", "--index"});
  addRunOutputOptions(*command, options->outputs);
  command->add_option("--image", options->image, "shaded image (PNG, EXR, ...)");
  command->add_option("--depth-image", options->depthImage,
                      "depth image: float t in EXR/TIFF, grey levels otherwise");
  command->add_option("--cost-image", options->costImage,
                      "cost heat map in the style of thesis figure 8.2");
  command->callback([options, request] {
    const Configuration configuration = request->resolve();
    checkOutputsOfModel(*options, *request, configuration);
    const RunConfig& settings = configuration.values();
    settings.camera.validate();
    if (settings.model != ModelKind::Golden) validate(options->outputs.traced(settings.rtu));
    checkOutputPaths(options->outputPaths(), inputPaths(settings));
    options->checkImageFormats();
    // The frame's images are each kind's own outputs.
    const RenderedFrame rendered = settings.rtu.core == BvhKind<>::kName
                                       ? renderBvh(configuration, *options)
                                       : renderSvo(configuration, *options);
    if (!options->image.empty()) writeShadedImage(rendered, options->image);
    if (!options->depthImage.empty()) writeDepthImage(rendered, options->depthImage);
    if (!options->costImage.empty()) writeCostImage(rendered, options->costImage);
    for (const std::string* path : {&options->image, &options->depthImage, &options->costImage})
      if (!path->empty()) std::cout << "wrote       " << *path << "\n";
  });
}

}  // namespace rtu
