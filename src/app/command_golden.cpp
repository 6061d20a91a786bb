#include <chrono>
#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/host_inputs.h"
#include "app/output_paths.h"
#include "app/schema_flags.h"
#include "inputs/host_buffers.h"
#include "kinds/svo/golden_model.h"
#include "kinds/svo/result_summary.h"
#include "kinds/svo/svo_image.h"

namespace rtu {

void addGoldenCommand(CLI::App& app) {
  struct Options {
    std::string out;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "golden", "replay a host input buffer (job or ray records) through the untimed bit-exact "
                "golden model");
  auto request = addConfigOptions(*command, kUseArithmetic | kUseBuffers);
  command->add_option("--out", options->out, "host output buffer to write")->required();
  command->callback([options, request] {
    const Configuration configuration = request->resolve();
    const RunConfig& settings = configuration.values();
    checkOneInputBuffer(settings);
    const GoldenConfig golden = settings.rtu.coreConfig<SvoKind>();
    const size_t recordWords = resultRecordWords(golden.format);
    checkOutputPaths({{"--out", options->out}}, inputPaths(settings));
    const SvoImage image = readSvoFile(settings.scene.svoFile);
    std::vector<SkippedRecord> skipped;
    const std::vector<TValueRecord> jobs =
        settings.rays.empty()
            ? readJobBufferSkipping(settings.jobs, skipped)
            : jobsFromRayRecords(image, readRayBufferSkipping(settings.rays, skipped),
                                 settings.rays, golden.epsilon);
    warnSkippedRecords(settings.rays.empty() ? "job buffer" : "ray buffer",
                       settings.rays.empty() ? settings.jobs : settings.rays, skipped, std::cout);
    checkInputTrees(image, jobs, golden.stackFrames, /*allowOverflow=*/true, settings);
    GoldenModel model(image.memory(), golden);
    const auto start = std::chrono::steady_clock::now();
    const std::vector<TraversalResult> results = model.traceAll(jobs);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    writeResultBuffer(options->out, results, recordWords);
    std::cout << ResultSummary::of(results).describe() << "host        " << seconds << " s\n"
              << "wrote " << options->out << "\n";
  });
}

}  // namespace rtu
