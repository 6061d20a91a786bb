#include <chrono>
#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/host_inputs.h"
#include "app/image_files.h"
#include "app/output_paths.h"
#include "app/results_csv.h"
#include "app/schema_flags.h"
#include "base/binary_file.h"
#include "inputs/host_buffers.h"
#include "kinds/svo/golden_model.h"
#include "kinds/svo/result_summary.h"
#include "kinds/svo/svo_image.h"

namespace rtu {
namespace {

struct GoldenOptions {
  std::string out, resultsCsv;
};

std::vector<ResultRow> svoRows(const std::vector<TraversalResult>& results,
                               const GoldenConfig& config) {
  std::vector<ResultRow> rows;
  rows.reserve(results.size());
  for (const TraversalResult& r : results)
    rows.push_back({r.id(), r.hit, r.hit ? SvoKind::hitDistance(r, config) : 0.0, {}, {}, {}, {}});
  return rows;
}

void goldenSvo(const RunConfig& settings, const GoldenOptions& options) {
  checkOneInputBuffer(settings);
  const GoldenConfig& golden = settings.rtu.coreConfig<SvoKind>();
  const SvoImage image = readSvoFile(settings.scene.svoFile);
  std::vector<SkippedRecord> skipped;
  const std::vector<TValueRecord> jobs =
      settings.rays.empty()
          ? readJobBufferSkipping(settings.jobs, skipped)
          : jobsFromRayRecords(image, readRayBufferSkipping(settings.rays, skipped), settings.rays,
                               golden.epsilon);
  warnSkippedRecords(settings.rays.empty() ? "job buffer" : "ray buffer",
                     settings.rays.empty() ? settings.jobs : settings.rays, skipped, std::cout);
  checkInputTrees(image, jobs, golden.stackFrames, settings.allowStackOverflow, settings);
  GoldenModel model(image.memory(), golden);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<TraversalResult> results = model.traceAll(jobs);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!options.out.empty())
    writeResultBuffer(options.out, results, resultRecordWords(golden.format));
  if (!options.resultsCsv.empty()) writeResultsCsv(options.resultsCsv, svoRows(results, golden));
  std::cout << ResultSummary::of(results).describe() << "host        " << seconds << " s\n";
}

void goldenTriangles(const RunConfig& settings, const GoldenOptions& options) {
  if (!settings.jobs.empty() || settings.rays.empty())
    throw std::invalid_argument(
        "a triangle image traces ray records: give --rays (job records are the SVO's t-values)");
  if (!options.out.empty())
    throw std::invalid_argument("--out: the host output buffer holds SVO results; for a triangle "
                                "image give --results-csv");
  const std::string kind =
      imageKindOf(readWordFile(settings.accel.file, sizeof(uint32_t), "triangle image"));
  if (kind.empty())
    throw std::invalid_argument("--accel-file '" + settings.accel.file + "' holds no " +
                                imageKindNames() + " image (an SVO image is given with --svo)");
  std::vector<SkippedRecord> skipped;
  const std::vector<RayRecord> rays = readRayBufferSkipping(settings.rays, skipped);
  warnSkippedRecords("ray buffer", settings.rays, skipped, std::cout);
  std::vector<ResultRow> rows;
  rows.reserve(rays.size());
  std::string summary;
  withImageKind(kind, [&](auto image) {
    summary = KindImageFile<decltype(image)>::golden(settings, rays, rows);
  });
  writeResultsCsv(options.resultsCsv, rows);
  std::cout << summary;
}

}  // namespace

void addGoldenCommand(CLI::App& app) {
  auto options = std::make_shared<GoldenOptions>();
  CLI::App* command = app.add_subcommand(
      "golden", "replay a host input buffer (job or ray records) through the untimed bit-exact "
                "golden model of an SVO image (--svo) or a triangle BVH or BIH (--accel-file)");
  auto request = addConfigOptions(*command, kUseArithmetic | kUseBuffers);
  command->add_option("--out", options->out, "host output buffer to write (SVO)");
  command->add_option("--results-csv", options->resultsCsv,
                      "results as CSV: id,hit,t,primitive,u,v, t along the record's direction");
  command->callback([options, request] {
    const Configuration configuration = request->resolve();
    const RunConfig& settings = configuration.values();
    if (options->out.empty() && options->resultsCsv.empty())
      throw std::invalid_argument("give --out (host output buffer) or --results-csv, or both");
    checkOutputPaths({{"--out", options->out}, {"--results-csv", options->resultsCsv}},
                     inputPaths(settings));
    if (!settings.accel.file.empty() && !settings.scene.svoFile.empty())
      throw std::invalid_argument("give one image: --svo or --accel-file, not both");
    if (settings.accel.file.empty())
      goldenSvo(settings, *options);
    else
      goldenTriangles(settings, *options);
    for (const std::string& path : {options->out, options->resultsCsv})
      if (!path.empty()) std::cout << "wrote " << path << "\n";
  });
}

}  // namespace rtu
