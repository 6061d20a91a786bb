#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/host_inputs.h"
#include "app/output_paths.h"
#include "app/run_outputs.h"
#include "app/schema_flags.h"
#include "app/triangle_replay.h"
#include "explore/sweep_workers.h"
#include "inputs/host_buffers.h"
#include "kinds/core_result.h"
#include "kinds/svo/result_summary.h"
#include "kinds/svo/svo_image.h"
#include "run/rtu_simulation.h"

namespace rtu {
namespace {

struct ReplayOptions {
  std::string out;
  RunOutputs outputs;
};

// A triangle core's replay (app/triangle_replay.h): ray records through an image file, the results
// as CSV rows in arrival order in --out.
void replayTriangles(const Configuration& configuration, const ReplayOptions& options) {
  const RunConfig& settings = configuration.values();
  const std::string& core = settings.rtu.core;
  if (settings.rays.empty() || !settings.jobs.empty())
    throw std::invalid_argument("replay --core " + core +
                                ": a triangle core traces ray records: give --rays (job records "
                                "are the SVO's t-values)");
  if (!settings.scene.svoFile.empty())
    throw std::invalid_argument("replay --core " + core +
                                ": --svo is the SVO core's image; give "
                                "the " +
                                core + " image with --accel-file");
  checkOutputsOfModel(options.outputs, settings.model);
  const RtuConfig config = options.outputs.traced(settings.rtu);
  validate(config);
  std::vector<NamedPath> outputs = options.outputs.paths();
  outputs.insert(outputs.begin(), NamedPath{"--out", options.out});
  checkOutputPaths(outputs, inputPaths(settings));
  std::vector<SkippedRecord> skipped;
  const std::vector<RayRecord> rays = readRayBufferSkipping(settings.rays, skipped);
  warnSkippedRecords("ray buffer", settings.rays, skipped, std::cout);
  const TriangleReplayInput input =
      triangleReplayInput(core, settings.accel.file, rays, settings.rays);
  const WordMemory memory(input.words);
  const RtuConfig planned = plannedTrace(memory, input.records, config, options.outputs, std::cout);
  RunProgressLine progress("replay", "rays");
  const RtuRun run = runModel(settings.model, memory, input.records, planned, progress.callback());
  const std::vector<ResultRow> rows = triangleResultRows(core, run.results, input.words);
  writeResultsCsv(options.out, rows);
  size_t hits = 0;
  for (const ResultRow& row : rows) hits += row.hit;
  std::cout << "rays        " << rows.size() << "\nhits        " << hits << "\n";
  reportRun(run, configuration, options.outputs, std::cout);
  std::cout << "wrote       " << options.out << "\n";
  if (config.trace) std::cout << "wrote       " << config.trace->path << "\n";
  if (config.timeline.wanted()) std::cout << "wrote       " << config.timeline.path << "\n";
}

}  // namespace

void addReplayCommand(CLI::App& app) {
  using Options = ReplayOptions;
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "replay", "replay a host input buffer through the cycle-accurate SystemC model of the RTU "
                "(or the loosely-timed or golden model: --model); a triangle core (--core bvh, "
                "bih, kd) traces ray records through an image file (--accel-file)");
  auto request =
      addConfigOptions(*command, kUseModel | kUseModelChoice | kUseArithmetic | kUseBuffers);
  command
      ->add_option("--out", options->out,
                   "host output buffer to write, in arrival order (a triangle core's: CSV "
                   "rows id,hit,t,primitive,u,v)")
      ->required();
  addRunOutputOptions(*command, options->outputs);
  command->callback([options, request] {
    const Configuration configuration = request->resolve();
    const RunConfig& settings = configuration.values();
    if (settings.rtu.core != SvoKind::kName) {
      replayTriangles(configuration, *options);
      return;
    }
    checkOneInputBuffer(settings);
    // The thesis' buffers: an .svo image, its job or ray records and its result records.
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
