#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <thread>

#include "app/animated_image.h"
#include "app/commands.h"
#include "app/frame_images.h"
#include "app/input_file_check.h"
#include "app/kind_animation.h"
#include "app/output_paths.h"
#include "app/plot_script.h"
#include "app/scene_shading.h"
#include "app/schema_flags.h"
#include "app/workers_option.h"
#include "base/choice_list.h"
#include "base/output_file.h"
#include "explore/animation_run.h"
#include "explore/animation_workers.h"
#include "explore/exploration_run.h"
#include "explore/sweep_workers.h"
#include "kind_app_plugins.h"
#include "run/lt_simulation.h"
#include "run/statistics_output.h"
#include "scene/model_cache.h"

namespace rtu {
namespace {

struct AnimateOptions {
  std::string sceneFile;
  SceneOverrides overrides;
  std::string outDir = "animation";
  std::string csv;
  std::string model = "golden";
  std::string cacheDir;
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  bool threadsGiven = false;
  int workers = 0;  // 0: one worker per core on the cycle-accurate model, one on golden
  bool noHitBuffer = false;
  bool traceAll = false;

  // The golden model traces a frame in `threads` threads already; the cycle-accurate and
  // loosely-timed ones simulate it in one.
  int workerCount() const {
    if (workers > 0) return workers;
    return model == "golden" ? 1 : defaultWorkerCount();
  }
  std::string csvPath() const { return csv.empty() ? outDir + "/frames.csv" : csv; }
  std::string framePath(int frame) const {
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%04d.png", frame);
    return outDir + name;
  }
};

// The loosely-timed model takes the golden scene manager's jobs as host records; in the hardware
// the host links carry rays into the scene manager and merged results out of it, not jobs. So
// paced links would time the wrong records: refused, as are the settings lt never models.
void refuseForLooselyTimedScenes(const RtuConfig& rtu) {
  if (const auto why = whyNotLooselyTimed(rtu))
    throw std::invalid_argument("--model lt does not apply: " + *why);
  if (rtu.hostInput.bytesPerCycle > 0 || rtu.hostOutput.bytesPerCycle > 0)
    throw std::invalid_argument(
        "animate --model lt does not model paced host links (they carry rays and merged results, "
        "the loosely-timed RTU sees jobs): set --host-in-bytes-per-cycle 0 "
        "--host-out-bytes-per-cycle 0, or use --model ca");
}

std::vector<SceneModel> loadModels(const SceneDescription& scene, const std::string& cacheDir) {
  std::vector<SceneModel> models;
  for (const ModelDescription& description : scene.models) {
    const auto start = std::chrono::steady_clock::now();
    models.push_back(loadSceneModel(description, cacheDir));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const SceneModel& model = models.back();
    std::printf("model       %s: %s, %s in %.2f s\n", model.name.c_str(),
                model.scene.summary.c_str(), model.fromCache ? "from the cache" : "built", seconds);
  }
  return models;
}

// `seconds`: the frames' wall-clock time, in `workers` workers.
void printSummary(const std::vector<FrameStatistics>& frames, double clockMhz,
                  const std::string& model, double seconds, int workers) {
  const FrameStatistics all = sumOf(frames);
  const uint64_t pixels = all.pixels, traced = all.raysTraced, saved = all.raysSaved,
                 jobs = all.jobs;
  const uint64_t cycles = all.cycles, culled = all.culled, early = all.earlyTerminations;
  const double host = all.hostSeconds;
  const double meanCycles = static_cast<double>(cycles) / frames.size();
  std::printf("frames      %zu, %.2f ms mean frame time at %.0f MHz (%.1f frames/s)\n",
              frames.size(), meanCycles / (clockMhz * 1e3), clockMhz,
              meanCycles > 0 ? clockMhz * 1e6 / meanCycles : 0.0);
  std::printf("rays        %llu traced, %llu saved by the hit buffer (%.1f %%)\n",
              static_cast<unsigned long long>(traced), static_cast<unsigned long long>(saved),
              pixels ? 100.0 * saved / pixels : 0.0);
  std::printf("jobs        %.3f per traced ray; %.3f instances culled per traced ray; %.1f %% of "
              "traced rays ended early\n",
              traced ? static_cast<double>(jobs) / traced : 0.0,
              traced ? static_cast<double>(culled) / traced : 0.0,
              traced ? 100.0 * early / traced : 0.0);
  std::printf("host        %.2f s in %d worker%s, %.2f s per frame (%s model)\n", seconds, workers,
              workers == 1 ? "" : "s", host / frames.size(), model.c_str());
}

void writeExtras(const AnimateOptions& options, const SceneDescription& scene,
                 const std::vector<std::string>& framePaths) {
  const std::string plot = options.outDir + "/frame_rate.png";
  std::fflush(stdout);  // the plotting script prints the plot's path after this run's lines
  try {
    runPlotScript("frames", {"--out", plot, options.csvPath()});
  } catch (const std::exception& error) {
    std::cerr << "rtusim animate: warning: no plot: " << error.what() << "\n";
  }
  const AnimatedImage animation =
      assembleAnimatedImage(framePaths, scene.frameRate, options.outDir + "/animation");
  if (animation.path.empty())
    std::cout << "animation   not assembled: install webp (img2webp) or ffmpeg\n";
  else
    std::cout << "wrote       " << animation.path << " (" << animation.tool << ")\n";
}

// The kinds with their own animation, as a message names them: "bvh".
std::string animatingCores() {
  std::vector<std::string> names;
  forEachCoreKind([&names](auto kind) {
    if constexpr (KindAnimation<decltype(kind)>::kAnimates) names.push_back(decltype(kind)::kName);
  });
  return choiceList(names);
}

// Runs the animation of a kind with its own (KindAnimation<Kind>), and returns true; false on the
// svo core, whose models' octrees the scene manager below merges per ray. Any other kind is
// refused, naming it.
bool animateWithKind(const AnimateOptions& options, const SceneDescription& scene,
                     const RunConfig& settings) {
  if (settings.rtu.core == SvoKind::kName) return false;
  withCoreKind(settings.rtu.core, [&](auto kind) {
    using Animation = KindAnimation<decltype(kind)>;
    if constexpr (Animation::kAnimates) {
      AnimationRequest request{&scene,
                               &settings,
                               parseModelKind(options.model),
                               options.csvPath(),
                               [&options](int frame) { return options.framePath(frame); },
                               options.threads};
      const std::vector<std::string> framePaths = Animation::run(request);
      std::cout << "wrote       " << options.outDir << "/frame_0000.png .. "
                << framePaths.back().substr(options.outDir.size() + 1) << ", " << options.csvPath()
                << "\n";
      writeExtras(options, scene, framePaths);
    } else {
      throw std::invalid_argument("animate --core " + settings.rtu.core +
                                  ": animated scenes run on the svo core (the scene manager) or "
                                  "the " +
                                  animatingCores() + " core (its own animation); the " +
                                  settings.rtu.core + " core has none");
    }
  });
  return true;
}

// The checks before any work: a kind with its own animation refuses the options it has no use for.
void refuseUnusedOptions(const AnimateOptions& options, const RunConfig& settings) {
  const std::string& core = settings.rtu.core;
  if (core == SvoKind::kName) {
    if (options.model == "lt") refuseForLooselyTimedScenes(settings.rtu);
    return;
  }
  withCoreKind(core, [&options](auto kind) {
    using Animation = KindAnimation<decltype(kind)>;
    if constexpr (Animation::kAnimates)
      Animation::refuse({options.noHitBuffer, options.traceAll, options.workers > 0,
                         options.threadsGiven ? options.threads : 0,
                         parseModelKind(options.model)});
  });
}

void animate(const AnimateOptions& options, const RunConfig& settings) {
  const RtuConfig& rtu = settings.rtu;
  refuseUnusedOptions(options, settings);
  const SceneDescription scene = readSceneFile(options.sceneFile, options.overrides);
  std::filesystem::create_directories(options.outDir);
  checkOutputPaths({{"--csv", options.csvPath()}, {"--out-dir", options.framePath(0)}},
                   {{"--scene-file", options.sceneFile}});
  checkImageFormat("--out-dir", options.framePath(0));
  std::printf("scene       %s: %zu models, %zu instances, %d frames of %dx%d at %.3g frames/s\n",
              scene.path.c_str(), scene.models.size(), scene.instances.size(), scene.frames,
              scene.width, scene.height, scene.frameRate);
  if (animateWithKind(options, scene, settings)) return;
  const std::vector<SceneModel> models =
      loadModels(scene, options.cacheDir.empty() ? defaultModelCacheDirectory() : options.cacheDir);

  AnimationOptions run{rtu.coreConfig<SvoKind>(),
                       {!options.traceAll, !options.traceAll},
                       !options.noHitBuffer,
                       options.threads,
                       rtu.cores,
                       rtu.clockMhz,
                       parseModelKind(options.model),
                       options.model == "golden" ? nullptr : &rtu};
  OutputFile csvFile(options.csvPath());
  std::ostream& csv = csvFile.stream();
  csv << csvLine(statisticsHeader<FrameStatistics>());
  std::vector<FrameStatistics> statistics;
  std::vector<std::string> framePaths;
  const auto writeFrame = [&options, &scene](const SceneFrame& rendered) {
    writeRgbImage(options.framePath(rendered.statistics.frame), scene.width, scene.height,
                  shadeSceneFrame(rendered, scene));
  };
  const int workers = std::min(options.workerCount(), scene.frames);
  const auto start = std::chrono::steady_clock::now();
  renderFramesInWorkers(scene, models, run, workers, writeFrame, [&](const FrameStatistics& frame) {
    framePaths.push_back(options.framePath(frame.frame));
    statistics.push_back(frame);
    csv << csvLine(statisticsFields(frame, "%.6g"));
  });
  csvFile.commit();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  printSummary(statistics, rtu.clockMhz, options.model, seconds, workers);
  std::cout << "wrote       " << options.outDir << "/frame_0000.png .. "
            << framePaths.back().substr(options.outDir.size() + 1) << ", " << options.csvPath()
            << "\n";
  writeExtras(options, scene, framePaths);
}

}  // namespace

void addAnimateCommand(CLI::App& app) {
  auto options = std::make_shared<AnimateOptions>();
  CLI::App* command = app.add_subcommand(
      "animate", "render an animated scene file (docs/scenes.md) frame by frame: images, an "
                 "animated image, per-frame statistics and a plot of the frame rate");
  auto request = addConfigOptions(*command, kUseModel | kUseArithmetic);
  command->add_option("--scene-file", options->sceneFile, "scene description (TOML)")
      ->required()
      ->check(regularInputFile());
  command
      ->add_option("--frames", options->overrides.frames, "frames to render (default: the file's)")
      ->check(CLI::Range(1, 100000));
  command->add_option("--width", options->overrides.width, "image width (default: the file's)")
      ->check(CLI::Range(1, 1 << 14));
  command->add_option("--height", options->overrides.height, "image height (default: the file's)")
      ->check(CLI::Range(1, 1 << 14));
  command->add_option("--out-dir", options->outDir, "directory for frames, CSV, plot, animation")
      ->capture_default_str();
  command->add_option("--csv", options->csv, "per-frame statistics (default: OUT-DIR/frames.csv)");
  command
      ->add_option("--model", options->model,
                   "golden (untimed; cycles from its costs and the RTU recurrence), ca "
                   "(cycle-accurate: the SystemC scene manager and RTU) or lt (the golden scene "
                   "manager's jobs through the loosely-timed RTU)")
      ->capture_default_str()
      ->check(CLI::IsMember({"golden", "ca", "lt"}));
  command->add_option("--cache-dir", options->cacheDir,
                      "where built models are kept (default: ~/.cache/rtusim/models)");
  CLI::Option* threads =
      command
          ->add_option("--threads", options->threads,
                       "threads tracing each frame's rays (svo); with --core bvh --model golden, "
                       "frames rendered in parallel")
          ->capture_default_str()
          ->check(CLI::Range(1, 256));
  addWorkersOption(*command, options->workers,
                   "worker processes rendering ranges of frames (default: all cores with "
                   "--model ca, 1 with golden)",
                   256);
  command->add_flag("--no-hit-buffer", options->noHitBuffer, "trace every pixel of every frame");
  command->add_flag("--trace-all", options->traceAll,
                    "no culling and no early termination: every instance for every ray");
  command->callback([options, request, threads] {
    options->threadsGiven = threads->count() > 0;
    const Configuration configuration = request->resolve();
    validate(configuration.values().rtu);
    animate(*options, configuration.values());
  });
}

}  // namespace rtu
