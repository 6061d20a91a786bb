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
    FrameOptions frame;
    double tolerance = 1e-3;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "accuracy",
      "compare the fixed-point golden model with the float64 reference, and the RTL "
      "float-to-fixed conversion with the exact one, on one frame");
  addFrameOptions(*command, options->frame);
  command->add_option("--tolerance", options->tolerance, "largest t difference that agrees")
      ->capture_default_str();
  command->callback([options] {
    const Scene scene = loadScene(options->frame.scene);
    const SvoMemory memory = scene.image.memory();
    const std::vector<Ray> rays = frameRays(options->frame.camera);
    const AccuracyReport report = measureAccuracy(memory, scene.image.root, rays, options->frame.config,
                                                  options->frame.epsilon, options->tolerance);
    std::cout << "scene       " << scene.name << ": " << scene.summary << "\n"
              << "golden      " << options->frame.config.format.describe() << ", "
              << toString(options->frame.config.conversion) << " conversion vs float64 reference\n"
              << report.describe();

    const std::vector<TraversalJob> jobs =
        makeFrameJobs(options->frame.camera, scene.image.root, options->frame.epsilon);
    GoldenConfig rtl = options->frame.config;
    rtl.conversion = FloatConversion::Rtl;
    GoldenConfig exact = options->frame.config;
    exact.conversion = FloatConversion::Exact;
    const size_t resultDifferences = countDifferences(GoldenModel(memory, rtl).traceAll(jobs),
                                                      GoldenModel(memory, exact).traceAll(jobs));
    std::cout << "rtl/exact   " << countConversionDifferences(jobs, options->frame.config.format)
              << " of " << jobs.size() * 6 << " t-values convert differently; "
              << resultDifferences << " of " << jobs.size() << " results differ\n";
  });
}

}  // namespace rtu
