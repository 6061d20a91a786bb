#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "app/commands.h"
#include "app/frame_image_writer.h"
#include "app/frame_images.h"
#include "app/frame_outputs.h"
#include "app/frame_stream.h"
#include "app/output_paths.h"
#include "app/raypipe_render.h"
#include "app/run_outputs.h"
#include "app/schema_flags.h"
#include "base/output_file.h"
#include "config/run_json.h"
#include "explore/frame_scene.h"
#include "explore/ray_passes.h"
#include "explore/sweep_workers.h"
#include "run/analytic_run.h"
#include "run/model_run.h"
#include "run/rtu_simulation.h"

namespace rtu {
namespace {

struct RenderOptions {
  RunOutputs outputs;
  std::string image, depthImage, costImage;
  RaypipeRenderOptions raypipe;

  std::vector<NamedPath> imagePaths() const {
    return {{"--image", image}, {"--depth-image", depthImage}, {"--cost-image", costImage}};
  }
  std::vector<NamedPath> outputPaths() const {
    std::vector<NamedPath> paths = outputs.paths();
    for (const std::vector<NamedPath>& more : {imagePaths(), raypipe.paths()})
      paths.insert(paths.end(), more.begin(), more.end());
    return paths;
  }
  bool wantsImages() const { return !image.empty() || !depthImage.empty() || !costImage.empty(); }
  void checkImageFormats() const {
    for (const NamedPath& file : imagePaths())
      if (!file.path.empty()) checkImageFormat(file.option, file.path);
    if (!raypipe.shadedImage.empty()) checkImageFormat("--shaded-image", raypipe.shadedImage);
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

// The frame's records on the chosen model, each result taken by `stream` as it leaves the run
// (none kept: app/frame_stream.h), with the model's report (the golden model's host time; a timed
// model's statistics, trace and timeline).
void traceFrame(const FrameScene& scene, FrameStream& stream, const Configuration& configuration,
                const RenderOptions& options, std::optional<RtuStatistics>& statistics) {
  const RunConfig& settings = configuration.values();
  const WordMemory memory = scene.memory();
  if (settings.model == ModelKind::Golden) {
    const auto start = std::chrono::steady_clock::now();
    traceGolden(memory, stream.records(), settings.rtu, stream.taker());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char host[128];
    std::snprintf(host, sizeof host, "host        %.3f s, %.2f M rays/s (golden model)\n", seconds,
                  static_cast<double>(stream.held().taken) / seconds / 1e6);
    std::cout << stream.describe() << host;
    return;
  }
  const RtuConfig config = options.outputs.traced(settings.rtu);
  // A trace's dry runs read the records more than once: a traced frame holds them.
  const bool traced = config.trace || config.timeline.wanted();
  const std::vector<HostRecord> held = traced ? stream.heldRecords() : std::vector<HostRecord>{};
  const RecordSource records = traced ? RecordSource(held) : stream.records();
  const RtuConfig planned = traced ? plannedTrace(memory, held, config, options.outputs, std::cout)
                                   : config;
  RunProgressLine progress("render", "rays");
  const RtuRun run =
      runFrame(settings.model, memory, records, planned, stream.taker(), progress.callback());
  statistics = run.statistics;
  std::cout << stream.describe();
  reportRun(run, configuration, options.outputs, std::cout);
  if (config.trace) std::cout << "wrote       " << config.trace->path << "\n";
  if (config.timeline.wanted()) std::cout << "wrote       " << config.timeline.path << "\n";
}

// One line of a pass: its rays and hits, and on a timed model its window of the frame's run.
void reportPass(const PassRun& pass, std::ostream& out) {
  const size_t hits = static_cast<size_t>(std::count(pass.hits.begin(), pass.hits.end(), true));
  char line[256];
  std::snprintf(line, sizeof line, "pass        %-10s %zu rays, %zu hits", toString(pass.type),
                pass.rays.size(), hits);
  out << line;
  if (pass.statistics) {
    const RtuStatistics& s = *pass.statistics;
    std::snprintf(line, sizeof line, ", %llu cycles (%.2f per ray), DRAM %.3f, limit %s",
                  static_cast<unsigned long long>(s.totalCycles), s.cyclesPerRay(),
                  s.utilisation().dramBandwidth, s.limit().empty() ? "none" : s.limit().c_str());
    out << line;
  }
  out << "\n";
}

// `statistics` written beside --stats s.json as s.<name>.json.
void writeBesideStats(const RtuStatistics& statistics, const std::string& name,
                      const Configuration& configuration, const RenderOptions& options) {
  const std::string& stats = options.outputs.statsPath;
  if (stats.empty()) return;
  const size_t dot = stats.find_last_of('.');
  const std::string path =
      (dot == std::string::npos ? stats : stats.substr(0, dot)) + "." + name + ".json";
  writeTextFile(path, runJson(statistics, configuration).dump(2) + "\n");
  std::cout << "wrote       " << path << "\n";
}

// The passes after the primary one: run with it as one workload (explore/ray_passes.h), each
// reported (and its statistics, and the whole frame's, written beside --stats: s.json ->
// s.shadow.json, s.frame.json), and their open shares shading the frame.
void renderPasses(const FrameScene& scene, const Configuration& configuration,
                  const RenderOptions& options, const std::vector<RayType>& passes,
                  const std::optional<RtuStatistics>& primary, RenderedFrame& frame) {
  const FramePassesRun run = runFramePasses(scene, configuration.values(), passes, primary);
  for (const PassRun& pass : run.passes) {
    reportPass(pass, std::cout);
    const std::vector<double> open = openShare(pass, frame.pixels.size());
    for (size_t p = 0; p < open.size(); ++p) {
      if (pass.type == RayType::Shadow) frame.pixels[p].lightOpen = static_cast<float>(open[p]);
      if (pass.type == RayType::Ao) frame.pixels[p].ambientOpen = static_cast<float>(open[p]);
    }
    if (pass.statistics)
      writeBesideStats(*pass.statistics, toString(pass.type), configuration, options);
  }
  if (!run.frame) return;
  writeBesideStats(*run.frame, "frame", configuration, options);
  std::cout << "frame       " << run.frame->rays << " rays in " << passes.size()
            << " passes as one run, " << run.frame->totalCycles << " cycles ("
            << run.frame->cyclesPerRay() << " per ray)\n";
}

// The frame of the run's kind (explore/frame_scene.h) on the chosen model, its passes and its
// images: written as the results leave the run, or, when secondary passes shade them, from the
// frame's pixels held for the passes.
void renderFrame(const Configuration& configuration, const RenderOptions& options) {
  const RunConfig& settings = configuration.values();
  const std::vector<RayType> passes = parseRayPasses(settings.rayPasses, "--passes");
  const FrameScene scene = loadFrameScene(settings);
  if (passes.size() > 1 && recordedWorkload(settings))
    throw std::invalid_argument("--passes " + settings.rayPasses +
                                ": secondary passes need the camera's frame, not recorded rays");
  // Pixels are held only for secondary passes, which read them all.
  const bool keepPixels = passes.size() > 1;
  const FrameImagePaths imagePaths{options.image, options.depthImage, options.costImage};
  const bool streamImages = !keepPixels && imagePaths.any();
  const RtuConfig traced = options.outputs.traced(settings.rtu);
  checkFrameFits(settings, keepPixels, FrameImageWriter::bytesPerPixel(imagePaths),
                 traced.trace || traced.timeline.wanted());
  std::optional<FrameImageWriter> images;
  if (streamImages) images.emplace(settings.camera, imagePaths);
  FrameStream stream(settings, scene, keepPixels, images ? &*images : nullptr);
  std::cout << "scene       " << scene.name << ": " << scene.description << "\n"
            << "model       " << toString(settings.model) << ", " << describeCore(settings) << "\n"
            << "frame       " << settings.camera.width << "x" << settings.camera.height << "\n";
  std::optional<RtuStatistics> primary;
  traceFrame(scene, stream, configuration, options, primary);
  if (images) images->finish();
  if (!keepPixels) return;
  RenderedFrame frame = *stream.takeFrame();
  renderPasses(scene, configuration, options, passes, primary, frame);
  if (!options.image.empty()) writeShadedImage(frame, options.image);
  if (!options.depthImage.empty()) writeDepthImage(frame, options.depthImage);
  if (!options.costImage.empty()) writeCostImage(frame, options.costImage);
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* command = app.add_subcommand(
      "render", "render one frame of primary rays on the cycle-accurate RTU model (or the "
                "loosely-timed or golden model: --model; or seed 001's ray pipe: --architecture "
                "raypipe) and report it");
  // The accel settings of the triangle cores' builds (--builder, --bih-format, --index, ...);
  // render builds the structure of its core, so not --accel.
  auto request = addConfigOptions(*command,
                                  kUseModel | kUseModelChoice | kUseArithmetic | kUseScene |
                                      kUseCamera | kUseAccel | kUseWorkload,
                                  {"--accel"});
  addRunOutputOptions(*command, options->outputs);
  command->add_option("--image", options->image,
                      "shaded image (PNG, EXR, ...); the ray pipe's: its simple shader's colours");
  command->add_option("--depth-image", options->depthImage,
                      "depth image: float t in EXR/TIFF, grey levels otherwise");
  command->add_option("--cost-image", options->costImage,
                      "cost heat map in the style of thesis figure 8.2");
  addRaypipeRenderOptions(*command, options->raypipe);
  command->callback([options, request] {
    const Configuration configuration = request->resolve();
    const RunConfig& settings = configuration.values();
    const bool raypipe = settings.architecture == Architecture::Raypipe;
    if (raypipe)
      checkRaypipeModel(settings.model);
    else
      checkRaypipeOnly(options->raypipe);
    checkOutputsOfModel(*options, *request, configuration);
    if (raypipe) {
      std::vector<NamedPath> inputs = inputPaths(settings);
      inputs.push_back({"--accel-file", options->raypipe.accelFile});
      checkOutputPaths(options->outputPaths(), inputs);
      options->checkImageFormats();
      renderRaypipe(configuration, {options->image, options->depthImage, options->costImage},
                    options->raypipe, options->outputs, std::cout);
      return;
    }
    settings.camera.validate();
    if (settings.model != ModelKind::Golden) validate(options->outputs.traced(settings.rtu));
    checkOutputPaths(options->outputPaths(), inputPaths(settings));
    options->checkImageFormats();
    renderFrame(configuration, *options);
    for (const std::string* path : {&options->image, &options->depthImage, &options->costImage})
      if (!path->empty()) std::cout << "wrote       " << *path << "\n";
  });
}

}  // namespace rtu
