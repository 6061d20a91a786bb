#include <iostream>
#include <memory>

#include "accuracy.h"
#include "cli_options.h"
#include "commands.h"

namespace rtu {

namespace {

// How many of the frame's t-values the two float-to-fixed conversions turn into different numbers.
size_t countConversionDifferences(const std::vector<TraversalJob>& jobs, const FixedFormat& format) {
  size_t differences = 0;
  for (const TraversalJob& job : jobs)
    for (const auto* bits : {&job.t0Bits, &job.t1Bits})
      for (uint32_t value : *bits)
        differences += floatToFixed(value, format, FloatConversion::Rtl) !=
                       floatToFixed(value, format, FloatConversion::Exact);
  return differences;
}

}  // namespace

void addAccuracyCommand(CLI::App& app) {
  struct Options {
    SceneSpec scene;
    Camera camera;
    double epsilon = kDefaultDirectionEpsilon;
    GoldenConfig config;
    double tolerance = 1e-3;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "accuracy",
      "compare the fixed-point golden model with the float64 reference, and the RTL "
      "float-to-fixed conversion with the exact one, on one frame");
  addSceneOptions(*command, options->scene);
  addCameraOptions(*command, options->camera, options->epsilon);
  addGoldenOptions(*command, options->config);
  command->add_option("--tolerance", options->tolerance, "largest t difference that agrees")
      ->capture_default_str();
  command->callback([options] {
    const Scene scene = loadScene(options->scene);
    const SvoMemory memory = scene.image.memory();
    const std::vector<Ray> rays = frameRays(options->camera);
    const AccuracyReport report = measureAccuracy(memory, scene.image.root, rays, options->config,
                                                  options->epsilon, options->tolerance);
    std::cout << "scene       " << scene.name << ": " << scene.summary << "\n"
              << "golden      " << options->config.format.describe() << ", "
              << toString(options->config.conversion) << " conversion vs float64 reference\n"
              << report.describe();

    const std::vector<TraversalJob> jobs =
        makeFrameJobs(options->camera, scene.image.root, options->epsilon);
    GoldenConfig rtl = options->config;
    rtl.conversion = FloatConversion::Rtl;
    GoldenConfig exact = options->config;
    exact.conversion = FloatConversion::Exact;
    const size_t resultDifferences = countDifferences(GoldenModel(memory, rtl).traceAll(jobs),
                                                      GoldenModel(memory, exact).traceAll(jobs));
    std::cout << "rtl/exact   " << countConversionDifferences(jobs, options->config.format)
              << " of " << jobs.size() * 6 << " t-values convert differently; "
              << resultDifferences << " of " << jobs.size() << " results differ\n";
  });
}

}  // namespace rtu
