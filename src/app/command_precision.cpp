// rtusim precision: one frame in a list of fixed-point formats against the float64 reference
// (src/kinds/svo/precision.h), as a table, a CSV and a difference image per format; with
// --triangles the triangle formats against the float64 watertight oracle
// (app/triangle_precision_report.h).

#include <cstdio>
#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/frame_images.h"
#include "app/output_paths.h"
#include "app/schema_flags.h"
#include "app/triangle_precision_report.h"
#include "base/output_file.h"
#include "explore/exploration_run.h"
#include "kinds/svo/precision.h"

namespace rtu {
namespace {

void printTable(const std::vector<FormatPrecision>& results, std::ostream& out) {
  char line[256];
  std::snprintf(line, sizeof line, "%-16s %10s %10s %10s %10s %9s %9s %11s %9s %8s %9s %9s\n",
                "format", "false hit", "missed hit", "hit/miss", "voxel", "t mean", "t p99",
                "t max", "cost", "cost", "t range", "< step");
  out << line;
  std::snprintf(line, sizeof line, "%-16s %10s %10s %10s %10s %9s %9s %11s %9s %8s %9s %9s\n", "",
                "%", "%", "%", "%", "steps", "steps", "steps", "/ray", "change", "%", "%");
  out << line;
  for (const FormatPrecision& p : results) {
    const double rays = static_cast<double>(p.rays ? p.rays : 1);
    std::snprintf(
        line, sizeof line,
        "%-16s %10.4f %10.4f %10.4f %10.4f %9.3g %9.3g %11.4g %9.2f %+7.2f%% %9.4f %9.4f\n",
        p.format.describe().c_str(), 100 * p.falseHitRate(), 100 * p.missedHitRate(),
        100 * p.wrongHitMissRate(), 100 * p.differentVoxelRate(), p.tErrorMeanSteps,
        p.tErrorP99Steps, p.tErrorMaxSteps, p.meanCost, 100 * p.costChange(),
        100.0 * static_cast<double>(p.tOverflowRays) / rays,
        100.0 * static_cast<double>(p.belowResolutionRays) / rays);
    out << line;
  }
}

void writeCsv(const std::vector<FormatPrecision>& results, const RunConfig& frame,
              const std::string& sceneName, const std::string& path) {
  OutputFile output(path);
  std::ostream& file = output.stream();
  file << csvLine({"scene",
                   "width",
                   "height",
                   "total_bits",
                   "fraction_bits",
                   "conversion",
                   "rays",
                   "reference_hits",
                   "false_hits",
                   "missed_hits",
                   "different_voxels",
                   "false_hit_rate",
                   "missed_hit_rate",
                   "wrong_hit_miss_rate",
                   "different_voxel_rate",
                   "t_error_mean_steps",
                   "t_error_p99_steps",
                   "t_error_max_steps",
                   "mean_cost",
                   "reference_mean_cost",
                   "cost_change",
                   "stack_overflows",
                   "t_overflows",
                   "wrong_unflagged",
                   "below_resolution"});
  for (const FormatPrecision& p : results)
    file << csvLine({sceneName,
                     std::to_string(frame.camera.width),
                     std::to_string(frame.camera.height),
                     std::to_string(p.format.totalBits),
                     std::to_string(p.format.fractionBits),
                     toString(frame.rtu.coreConfig<SvoKind>().conversion),
                     std::to_string(p.rays),
                     std::to_string(p.referenceHits),
                     std::to_string(p.falseHits),
                     std::to_string(p.missedHits),
                     std::to_string(p.differentVoxels),
                     precisionFigure(p.falseHitRate()),
                     precisionFigure(p.missedHitRate()),
                     precisionFigure(p.wrongHitMissRate()),
                     precisionFigure(p.differentVoxelRate()),
                     precisionFigure(p.tErrorMeanSteps),
                     precisionFigure(p.tErrorP99Steps),
                     precisionFigure(p.tErrorMaxSteps),
                     precisionFigure(p.meanCost),
                     precisionFigure(p.referenceMeanCost),
                     precisionFigure(p.costChange()),
                     std::to_string(p.overflowRays),
                     std::to_string(p.tOverflowRays),
                     std::to_string(p.wrongUnflagged),
                     std::to_string(p.belowResolutionRays)});
  output.commit();
}

// The triangle study's flags, each only with --triangles; the parameters are named as seed 004
// names them.
void addTriangleOptions(CLI::App& command, TrianglePrecisionOptions& o, CLI::Option* triangles) {
  TriangleSweep& s = o.sweep;
  const std::pair<const char*, std::vector<int>*> lists[] = {
      {"--n", &s.n}, {"--m", &s.m}, {"--E", &s.E}, {"--T", &s.T}, {"--C", &s.C}};
  const char* const help[] = {"grid bits n to sweep (the prototype's 29 is always measured)",
                              "vector bits m to sweep (prototype 32)",
                              "edge shift E to sweep (prototype 10)",
                              "dropped division bits T to sweep (prototype 0)",
                              "inverse-direction fraction bits C to sweep (prototype 16)"};
  for (int i = 0; i < 5; ++i)
    command.add_option(lists[i].first, *lists[i].second, help[i])
        ->delimiter(',')
        ->capture_default_str()
        ->needs(triangles);
  command.add_option("--views", o.rays.views, "views around the mesh's box")
      ->capture_default_str()
      ->needs(triangles);
  command.add_option("--view-size", o.rays.viewSize, "rays per view: this many squared")
      ->capture_default_str()
      ->needs(triangles);
  command.add_option("--random-rays", o.rays.randomRays, "rays from inside the box")
      ->capture_default_str()
      ->needs(triangles);
  command
      .add_option("--aimed-rays", o.rays.aimedRays,
                  "rays aimed at vertices and edge midpoints (holes: the shared ones)")
      ->capture_default_str()
      ->needs(triangles);
  command
      .add_flag("--drop-bad-triangles", o.dropBadTriangles,
                "drop degenerate and duplicate triangles instead of refusing the mesh")
      ->needs(triangles);
  command.add_option("--ray-seed", o.rays.seed, "the random and aimed rays' seed")
      ->capture_default_str()
      ->needs(triangles);
  command
      .add_option("--stress-size", o.stressWidth,
                  "the stress triangle's view width (height 3/4 of it; 0: no stress rows)")
      ->capture_default_str()
      ->needs(triangles);
}

}  // namespace

void addPrecisionCommand(CLI::App& app) {
  struct Options {
    std::vector<std::string> formats = {"Q8.8",   "Q10.10", "Q12.12", "Q14.14", "Q16.16",
                                        "Q12.20", "Q20.20", "Q24.24", "Q16.32"};
    std::string csv, imageDirectory;
    bool triangles = false;
    TrianglePrecisionOptions triangle;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "precision",
      "one frame in several fixed-point formats against the float64 reference: false and missed "
      "hits, hits on another voxel, t error in steps of each format, cost");
  // The formats come from --formats, and the stack is as deep as any tree (kMaxStackFrames), so
  // that only the arithmetic differs.
  auto request = addConfigOptions(*command, kUseArithmetic | kUseScene | kUseCamera,
                                  {"--total-bits", "--fraction-bits", "--stack-frames",
                                   "--allow-stack-overflow"});
  command
      ->add_option("--formats", options->formats,
                   "formats as QI.F: I integer bits with the sign, F fraction bits (Q16.16 is "
                   "32 bits); a bare I.F only where it reads as one format")
      ->delimiter(',')
      ->capture_default_str();
  command->add_option("--csv", options->csv, "write one row per format");
  command->add_option("--images", options->imageDirectory,
                      "write a difference image per format into this folder, created if "
                      "missing (precision_QI_F.png)");
  CLI::Option* triangles = command->add_flag(
      "--triangles", options->triangles,
      "the triangle formats instead (seed 004's fixed point, seed 001's binary32, float32) on the "
      "scene's triangles (docs/precision.md, \"Triangle formats\")");
  triangles->excludes("--formats")->excludes("--images");
  addTriangleOptions(*command, options->triangle, triangles);
  command->callback([options, request] {
    const Configuration configuration = request->resolve();
    const RunConfig& frame = configuration.values();
    if (options->triangles) {
      options->triangle.csv = options->csv;
      return runTrianglePrecision(options->triangle, frame);
    }
    std::vector<FixedFormat> formats;
    for (const std::string& text : options->formats) formats.push_back(parseFixedFormat(text));
    frame.camera.validate();
    if (!options->imageDirectory.empty()) createOutputFolder({"--images", options->imageDirectory});
    const Scene scene = loadScene(frame.scene);
    PrecisionStudy study;
    study.rays = frameRays(frame.camera);
    study.root = scene.image.root;
    study.conversion = frame.rtu.coreConfig<SvoKind>().conversion;
    study.epsilon = frame.epsilon;
    const std::vector<FormatPrecision> results =
        measurePrecision(scene.image.memory(), study, formats);
    std::cout << "scene " << scene.name << ", " << frame.camera.width << "x" << frame.camera.height
              << ", " << toString(study.conversion) << " conversion; against float64 ("
              << results.front().referenceHits << " hits of " << study.rays.size() << " rays)\n";
    printTable(results, std::cout);
    if (!options->csv.empty()) {
      writeCsv(results, frame, scene.name, options->csv);
      std::cout << "wrote " << options->csv << "\n";
    }
    if (!options->imageDirectory.empty()) {
      for (const FormatPrecision& p : results) {
        const std::string path = options->imageDirectory + "/precision_Q" +
                                 std::to_string(p.format.totalBits - p.format.fractionBits) + "_" +
                                 std::to_string(p.format.fractionBits) + ".png";
        writePrecisionImage(frame.camera, p.verdicts, path);
        std::cout << "wrote " << path << "\n";
      }
    }
  });
}

}  // namespace rtu
