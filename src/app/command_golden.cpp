#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include "app/bih_golden.h"
#include "app/bvh_golden.h"
#include "app/commands.h"
#include "app/host_inputs.h"
#include "app/output_paths.h"
#include "app/results_csv.h"
#include "app/schema_flags.h"
#include "base/binary_file.h"
#include "inputs/host_buffers.h"
#include "kinds/bih/bih_file.h"
#include "kinds/bvh/bvh_file.h"
#include "kinds/kd/kd_image.h"
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

std::string triangleSummary(size_t rays, size_t hits, uint64_t cost, uint64_t nodes,
                            uint64_t triangles, double seconds) {
  const double n = rays == 0 ? 1.0 : static_cast<double>(rays);
  char text[320];
  std::snprintf(text, sizeof text,
                "rays        %zu\nhits        %zu (%.1f %%)\ncost        mean %.2f states per ray\n"
                "per ray     %.2f nodes, %.2f triangle tests\nhost        %g s\n",
                rays, hits, 100.0 * hits / n, cost / n, nodes / n, triangles / n, seconds);
  return text;
}

size_t hitsOf(const std::vector<ResultRow>& rows) {
  size_t hits = 0;
  for (const ResultRow& row : rows) hits += row.hit;
  return hits;
}

// The BVH's rows and report (a .bvh image, in the world).
std::string goldenBvh(const RunConfig& settings, const std::vector<RayRecord>& rays,
                      std::vector<ResultRow>& rows) {
  const BvhImage image = readBvhFile(settings.accel.file);
  const BvhGoldenRun run = traceBvhGolden(image.words, rays, settings.rays,
                                          settings.rtu.coreConfig<BvhKind<>>().triangleTest);
  uint64_t cost = 0, nodes = 0, triangles = 0;
  for (const BvhResult& r : run.results) {
    cost += r.cost;
    nodes += r.counts.nodes;
    triangles += r.counts.triangleTests;
    rows.push_back({r.idWord, r.hit, r.t, r.primitive, r.u, r.v, {}});
  }
  return triangleSummary(rows.size(), hitsOf(rows), cost, nodes, triangles, run.seconds);
}

// The BIH's rows and report (a .bih image, on its grid).
std::string goldenBih(const RunConfig& settings, const std::vector<RayRecord>& rays,
                      std::vector<ResultRow>& rows) {
  const BihImage image = readBihFile(settings.accel.file);
  for (const std::string& warning : image.warnings) std::cerr << "warning: " << warning << "\n";
  BihGoldenRun run = traceBihGolden(image.words, rays, settings.rays);
  rows = std::move(run.rows);
  return triangleSummary(rows.size(), hitsOf(rows), run.cost, run.nodes, run.triangleTests,
                         run.seconds);
}

void goldenTriangles(const RunConfig& settings, const GoldenOptions& options) {
  if (!settings.jobs.empty() || settings.rays.empty())
    throw std::invalid_argument(
        "a triangle image traces ray records: give --rays (job records are the SVO's t-values)");
  if (!options.out.empty())
    throw std::invalid_argument("--out: the host output buffer holds SVO results; for a triangle "
                                "image give --results-csv");
  const std::vector<uint32_t> words =
      readWordFile(settings.accel.file, sizeof(uint32_t), "triangle image");
  if (!words.empty() && words[0] == kKdMagic)
    throw std::invalid_argument(
        "--accel-file '" + settings.accel.file +
        "' is a k-d image: golden traces BVH and BIH images (a k-d tree "
        "image or scene file is traced by the ray pipe: render --architecture raypipe "
        "--model golden --accel-file FILE)");
  const bool bih = looksLikeBihImage(words);
  std::vector<SkippedRecord> skipped;
  const std::vector<RayRecord> rays = readRayBufferSkipping(settings.rays, skipped);
  warnSkippedRecords("ray buffer", settings.rays, skipped, std::cout);
  std::vector<ResultRow> rows;
  rows.reserve(rays.size());
  const std::string summary = bih ? goldenBih(settings, rays, rows)
                                  : goldenBvh(settings, rays, rows);
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
