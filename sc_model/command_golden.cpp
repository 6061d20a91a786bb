#include <chrono>
#include <iostream>
#include <memory>
#include <set>

#include "cli_options.h"
#include "commands.h"
#include "golden_model.h"
#include "host_buffers.h"
#include "result_summary.h"
#include "svo_image.h"
#include "svo_validator.h"

namespace rtu {

namespace {

// Every root the jobs name must hold a valid tree that the configured stack can traverse.
void validateRoots(SvoImage image, const std::vector<TraversalJob>& jobs, int stackFrames) {
  std::set<uint32_t> roots;
  for (const TraversalJob& job : jobs) roots.insert(job.root);
  for (uint32_t root : roots) {
    image.root = root;
    const SvoReport report = validateSvo(image, SvoLimits{});
    if (report.depth - 1 > stackFrames)
      std::cerr << "rtusim: warning: the tree at root " << root << " has depth " << report.depth
                << " and needs " << report.depth - 1 << " stack frames; " << stackFrames
                << " are configured, deeper rays will be flagged\n";
  }
}

}  // namespace

void addGoldenCommand(CLI::App& app) {
  struct Options {
    std::string svo, jobs, out;
    GoldenConfig config;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "golden", "replay a host input buffer through the untimed bit-exact golden model");
  command->add_option("--svo", options->svo, "SVO memory image")->required()->check(CLI::ExistingFile);
  command->add_option("--jobs", options->jobs, "host input buffer (8 u32 per job)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", options->out, "host output buffer to write")->required();
  addGoldenOptions(*command, options->config);
  command->callback([options] {
    const SvoImage image = readSvoFile(options->svo);
    const std::vector<TraversalJob> jobs = readJobBuffer(options->jobs);
    validateRoots(image, jobs, options->config.stackFrames);
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
