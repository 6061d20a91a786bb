#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/placement_flags.h"
#include "app/schema_flags.h"
#include "inputs/host_buffers.h"

namespace rtu {

namespace {

void reportWritten(size_t records, const std::string& kind, const std::string& path) {
  std::cout << "wrote " << records << " " << kind << " (" << records * kRecordBytes << " bytes) to "
            << path << "\n";
}

}  // namespace

void addJobsCommand(CLI::App& app) {
  struct Options {
    uint32_t root = 0;
    std::string out;
    std::string rays;
    uint32_t modelAddress = 0;
  };
  auto options = std::make_shared<Options>();
  CLI::App* command = app.add_subcommand(
      "jobs", "write one frame's primary rays as host job records (thesis driver format) or as "
              "ray records for an animated model");
  auto request = addConfigOptions(*command, kUseCamera);
  command->add_option("--root", options->root, "root descriptor address written into each job")
      ->capture_default_str()
      ->check(kNotNegative);
  CLI::Option* out = command->add_option("--out", options->out, "output job buffer");
  CLI::Option* rays =
      command->add_option("--rays", options->rays, "output ray buffer (world-space ray records)");
  CLI::Option* modelAddress = command->add_option(
      "--model-address", options->modelAddress,
      "word address of the model header written into each ray record (see build --model-header)");
  modelAddress->check(kNotNegative);
  rays->needs(modelAddress);
  modelAddress->needs(rays);
  command->callback([options, request, out, rays] {
    const Configuration configuration = request->resolve();
    const Camera& camera = configuration.values().camera;
    camera.validate();
    if (!*out && !*rays)
      throw std::invalid_argument("give --out (job records), --rays (ray records) or both");
    if (*out) {
      const std::vector<TValueRecord> jobs =
          makeFrameJobs(camera, options->root, configuration.values().epsilon);
      writeJobBuffer(options->out, jobs);
      reportWritten(jobs.size(), "jobs", options->out);
    }
    if (*rays) {
      const std::vector<RayRecord> records = makeFrameRayRecords(camera, options->modelAddress);
      writeRayBuffer(options->rays, records);
      reportWritten(records.size(), "ray records", options->rays);
    }
  });
}

}  // namespace rtu
