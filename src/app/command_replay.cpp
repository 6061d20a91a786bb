#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/host_inputs.h"
#include "app/output_paths.h"
#include "app/run_outputs.h"
#include "app/schema_flags.h"
#include "explore/sweep_workers.h"
#include "inputs/host_buffers.h"
#include "kinds/core_result.h"
#include "kinds/svo/result_summary.h"
#include "kinds/svo/svo_image.h"
#include "run/rtu_simulation.h"

namespace rtu {

void addReplayCommand(CLI::App& app) {
  struct Options {
    std::string out;
    RunOutputs outputs;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "replay", "replay a host input buffer through the cycle-accurate SystemC model of the RTU "
                "(or the loosely-timed or golden model: --model)");
  auto request =
      addConfigOptions(*command, kUseModel | kUseModelChoice | kUseArithmetic | kUseBuffers);
  command->add_option("--out", options->out, "host output buffer to write, in arrival order")
      ->required();
  addRunOutputOptions(*command, options->outputs);
  command->callback([options, request] {
    const Configuration configuration = request->resolve();
    const RunConfig& settings = configuration.values();
    checkOneInputBuffer(settings);
    // The thesis' buffers: an .svo image, its job or ray records and its result records.
    if (settings.rtu.core != SvoKind::kName)
      throw std::invalid_argument("replay --core " + settings.rtu.core +
                                  ": replay runs the thesis' SVO buffers only; trace triangle "
                                  "ray records with golden --accel-file");
    checkOutputsOfModel(options->outputs, settings.model);
    const RtuConfig config = options->outputs.traced(settings.rtu);
    validate(config);
    const GoldenConfig& svo = config.coreConfig<SvoKind>();
    const size_t recordWords = resultRecordWords(svo.format);
    std::vector<NamedPath> outputs = options->outputs.paths();
    outputs.insert(outputs.begin(), NamedPath{"--out", options->out});
    checkOutputPaths(outputs, inputPaths(settings));
    const SvoImage image = readSvoFile(settings.scene.svoFile);
    std::vector<HostRecord> records;
    std::vector<SkippedRecord> skipped;
    if (!settings.rays.empty()) {
      const std::vector<RayRecord> rays = readRayBufferSkipping(settings.rays, skipped);
      // The job manager's own set-up, run ahead once to check every header and tree up front;
      // only the checks read these jobs (the run reads the records), so they go at the block's end.
      const std::vector<TValueRecord> jobs =
          jobsFromRayRecords(image, rays, settings.rays, svo.epsilon);
      records.assign(rays.begin(), rays.end());
      warnSkippedRecords("ray buffer", settings.rays, skipped, std::cout);
      checkInputTrees(image, jobs, svo.stackFrames, settings.allowStackOverflow, settings);
    } else {
      records = readJobRecordsSkipping(settings.jobs, skipped);
      warnSkippedRecords("job buffer", settings.jobs, skipped, std::cout);
      checkInputTrees(image, records, svo.stackFrames, settings.allowStackOverflow, settings);
    }
    const RtuConfig planned =
        plannedTrace(image.memory(), records, config, options->outputs, std::cout);
    RunProgressLine progress("replay", "rays");
    const RtuRun run =
        runModel(settings.model, image.memory(), records, planned, progress.callback());
    // The thesis' result buffer is the SVO kind's output.
    const std::vector<TraversalResult> results = svoResults(run.results);
    writeResultBuffer(options->out, results, recordWords);
    std::cout << ResultSummary::of(results).describe();
    reportRun(run, configuration, options->outputs, std::cout);
    std::cout << "wrote       " << options->out << "\n";
    if (config.trace) std::cout << "wrote       " << config.trace->path << "\n";
    if (config.timeline.wanted()) std::cout << "wrote       " << config.timeline.path << "\n";
  });
}

}  // namespace rtu
