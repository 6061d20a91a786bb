#include <iostream>
#include <memory>

#include "cli_options.h"
#include "commands.h"
#include "host_buffers.h"
#include "result_summary.h"
#include "rtu_options.h"
#include "rtu_simulation.h"
#include "svo_image.h"

namespace rtu {

void addReplayCommand(CLI::App& app) {
  struct Options {
    std::string svo, jobs, out;
    GoldenConfig golden;
    RtuOptions rtu;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "replay", "replay a host input buffer through the cycle-accurate SystemC model of the RTU");
  command->add_option("--svo", options->svo, "SVO memory image")->required()->check(CLI::ExistingFile);
  command->add_option("--jobs", options->jobs, "host input buffer (8 u32 per job record)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", options->out, "host output buffer to write, in arrival order")
      ->required();
  addGoldenOptions(*command, options->golden);
  addRtuOptions(*command, options->rtu);
  command->callback([options] {
    const SvoImage image = readSvoFile(options->svo);
    const std::vector<TraversalJob> jobs = readJobBuffer(options->jobs);
    const RtuConfig config = options->rtu.resolve(options->golden);
    validate(config);
    checkStackDepth(image, jobs, config.stackFrames, options->rtu.allowStackOverflow);
    const RtuRun run = simulateRtu(image.memory(), jobs, config);
    writeResultBuffer(options->out, run.results);
    std::cout << ResultSummary::of(run.results).describe();
    reportRun(run, options->rtu, std::cout);
    std::cout << "wrote       " << options->out << "\n";
    if (config.trace) std::cout << "wrote       " << config.trace->path << "\n";
  });
}

}  // namespace rtu
