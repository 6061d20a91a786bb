#include <chrono>
#include <iostream>
#include <memory>

#include "cli_options.h"
#include "commands.h"
#include "golden_model.h"
#include "host_buffers.h"
#include "result_summary.h"
#include "svo_image.h"
#include "stack_check.h"

namespace rtu {

namespace {

// The job manager's set-up of world-space ray records against the model headers in the image.
std::vector<TraversalJob> jobsFromRayBuffer(const SvoImage& image, const std::string& path,
                                            double epsilon) {
  const std::vector<RayRecord> records = readRayBuffer(path);
  try {
    return rayRecordsToJobs(image.memory(), records, static_cast<float>(epsilon));
  } catch (const std::runtime_error& error) {
    throw std::runtime_error("ray buffer '" + path + "': " + error.what());
  }
}

}  // namespace

void addGoldenCommand(CLI::App& app) {
  struct Options {
    std::string svo, jobs, rays, out;
    double epsilon = kDefaultDirectionEpsilon;
    GoldenConfig config;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "golden", "replay a host input buffer (job or ray records) through the untimed bit-exact "
      "golden model");
  command->add_option("--svo", options->svo, "SVO memory image")->required()->check(CLI::ExistingFile);
  CLI::Option* jobs =
      command->add_option("--jobs", options->jobs, "host input buffer (8 u32 per job)")
          ->check(CLI::ExistingFile);
  CLI::Option* rays =
      command->add_option("--rays", options->rays, "ray buffer (8 u32 per world-space ray record)")
          ->check(CLI::ExistingFile)
          ->excludes(jobs);
  command->add_option("--epsilon", options->epsilon,
                      "job manager: direction components below epsilon times the largest count "
                      "as zero (--rays)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0))
      ->needs(rays);
  command->add_option("--out", options->out, "host output buffer to write")->required();
  addGoldenOptions(*command, options->config);
  command->callback([options] {
    if (options->jobs.empty() && options->rays.empty())
      throw std::invalid_argument("give the input: --jobs (job records) or --rays (ray records)");
    const SvoImage image = readSvoFile(options->svo);
    const std::vector<TraversalJob> jobs =
        options->rays.empty() ? readJobBuffer(options->jobs)
                              : jobsFromRayBuffer(image, options->rays, options->epsilon);
    checkStackDepth(image, jobs, options->config.stackFrames, /*allowOverflow=*/true);
    GoldenModel model(image.memory(), options->config);
    const auto start = std::chrono::steady_clock::now();
    const std::vector<TraversalResult> results = model.traceAll(jobs);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    writeResultBuffer(options->out, results);
    std::cout << ResultSummary::of(results).describe() << "host        " << seconds << " s\n"
              << "wrote " << options->out << "\n";
  });
}

}  // namespace rtu
