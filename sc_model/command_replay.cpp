#include <iostream>
#include <memory>

#include "cli_options.h"
#include "commands.h"
#include "host_buffers.h"
#include "result_summary.h"
#include "rtu_options.h"
#include "rtu_simulation.h"
#include "stack_check.h"
#include "svo_image.h"

namespace rtu {

void addReplayCommand(CLI::App& app) {
  struct Options {
    std::string svo, jobs, rays, out;
    GoldenConfig golden;
    RtuOptions rtu;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "replay", "replay a host input buffer through the cycle-accurate SystemC model of the RTU");
  command->add_option("--svo", options->svo, "SVO memory image")->required()->check(CLI::ExistingFile);
  CLI::Option* jobs =
      command->add_option("--jobs", options->jobs, "host input buffer (8 u32 per job record)")
          ->check(CLI::ExistingFile);
  command->add_option("--rays", options->rays, "ray buffer (8 u32 per world-space ray record)")
      ->check(CLI::ExistingFile)
      ->excludes(jobs);
  command->add_option("--epsilon", options->rtu.config.jobManager.epsilon,
                      "job manager: direction components below epsilon times the largest count "
                      "as zero (--rays)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  command->add_option("--out", options->out, "host output buffer to write, in arrival order")
      ->required();
  addGoldenOptions(*command, options->golden);
  addRtuOptions(*command, options->rtu);
  command->callback([options] {
    if (options->jobs.empty() == options->rays.empty())
      throw std::invalid_argument("give the input: --jobs (job records) or --rays (ray records)");
    const SvoImage image = readSvoFile(options->svo);
    const RtuConfig config = options->rtu.resolve(options->golden);
    validate(config);
    std::vector<HostRecord> records;
    std::vector<TraversalJob> jobs;
    if (!options->rays.empty()) {
      const std::vector<RayRecord> rays = readRayBuffer(options->rays);
      // The job manager's own set-up, run ahead once to check every header and tree up front.
      jobs = rayRecordsToJobs(image.memory(), rays, config.jobManager.epsilon);
      records.assign(rays.begin(), rays.end());
    } else {
      jobs = readJobBuffer(options->jobs);
      records.assign(jobs.begin(), jobs.end());
    }
    checkStackDepth(image, jobs, config.stackFrames, options->rtu.allowStackOverflow);
    const RtuRun run = simulateRtu(image.memory(), records, config);
    writeResultBuffer(options->out, run.results);
    std::cout << ResultSummary::of(run.results).describe();
    reportRun(run, options->rtu, std::cout);
    std::cout << "wrote       " << options->out << "\n";
    if (config.trace) std::cout << "wrote       " << config.trace->path << "\n";
  });
}

}  // namespace rtu
