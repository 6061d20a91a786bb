#include <iostream>
#include <memory>

#include "cli_options.h"
#include "commands.h"
#include "host_buffers.h"

namespace rtu {

void addJobsCommand(CLI::App& app) {
  struct Options {
    Camera camera;
    double epsilon = kDefaultDirectionEpsilon;
    uint32_t root = 0;
    std::string out;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "jobs", "write the host input buffer of one frame's primary rays (thesis driver format)");
  addCameraOptions(*command, options->camera, options->epsilon);
  command->add_option("--root", options->root, "root descriptor address written into each job")
      ->capture_default_str();
  command->add_option("--out", options->out, "output job buffer")->required();
  command->callback([options] {
    const std::vector<TraversalJob> jobs =
        makeFrameJobs(options->camera, options->root, options->epsilon);
    writeJobBuffer(options->out, jobs);
    std::cout << "wrote " << jobs.size() << " jobs (" << jobs.size() * kRecordBytes
              << " bytes) to " << options->out << "\n";
  });
}

}  // namespace rtu
