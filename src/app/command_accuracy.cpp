#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/schema_flags.h"
#include "kinds/svo/accuracy.h"
#include "kinds/svo/stack_check.h"

namespace rtu {

namespace {

// How many of the frame's t-values the two float-to-fixed conversions turn into different numbers.
size_t countConversionDifferences(const std::vector<TValueRecord>& jobs,
                                  const FixedFormat& format) {
  size_t differences = 0;
  for (const TValueRecord& job : jobs)
    for (const auto* bits : {&job.t0Bits, &job.t1Bits})
      for (uint32_t value : *bits)
        differences += floatToFixed(value, format, FloatConversion::Rtl) !=
                       floatToFixed(value, format, FloatConversion::Exact);
  return differences;
}

}  // namespace

void addAccuracyCommand(CLI::App& app) {
  struct Options {
    double tolerance = 1e-3;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "accuracy", "compare the fixed-point golden model with the float64 reference, and the RTL "
                  "float-to-fixed conversion with the exact one, on one frame");
  auto request = addConfigOptions(*command, kUseArithmetic | kUseScene | kUseCamera);
  command->add_option("--tolerance", options->tolerance, "largest t difference that agrees")
      ->capture_default_str();
  command->callback([options, request] {
    const Configuration configuration = request->resolve();
    const RunConfig& frame = configuration.values();
    const GoldenConfig golden = frame.rtu.coreConfig<SvoKind>();
    golden.format.validate();
    frame.camera.validate();
    checkBuiltSceneFitsStack(frame.scene, golden.stackFrames, frame.allowStackOverflow);
    const Scene scene = loadScene(frame.scene);
    checkRootDepths(scene.image, {scene.image.root}, golden.stackFrames, frame.allowStackOverflow,
                    sceneSource(frame.scene));
    const WordMemory memory = scene.image.memory();
    const std::vector<Ray> rays = frameRays(frame.camera);
    const AccuracyReport report =
        measureAccuracy(memory, scene.image.root, rays, golden, frame.epsilon, options->tolerance);
    std::cout << "scene       " << scene.name << ": " << scene.summary << "\n"
              << "golden      " << golden.format.describe() << ", " << toString(golden.conversion)
              << " conversion vs float64 reference\n"
              << report.describe();

    const std::vector<TValueRecord> jobs =
        makeFrameJobs(frame.camera, scene.image.root, frame.epsilon);
    GoldenConfig rtl = golden;
    rtl.conversion = FloatConversion::Rtl;
    GoldenConfig exact = golden;
    exact.conversion = FloatConversion::Exact;
    const size_t resultDifferences = countDifferences(GoldenModel(memory, rtl).traceAll(jobs),
                                                      GoldenModel(memory, exact).traceAll(jobs));
    std::cout << "rtl/exact   " << countConversionDifferences(jobs, golden.format) << " of "
              << jobs.size() * 6 << " t-values convert differently; " << resultDifferences << " of "
              << jobs.size() << " results differ\n";
  });
}

}  // namespace rtu
