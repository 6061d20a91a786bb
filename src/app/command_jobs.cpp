#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/placement_flags.h"
#include "app/ray_workload_options.h"
#include "app/schema_flags.h"
#include "inputs/host_buffers.h"
#include "kinds/svo/svo_image.h"

namespace rtu {

namespace {

void reportWritten(size_t records, const std::string& kind, const std::string& path) {
  std::cout << "wrote " << records << " " << kind << " (" << records * kRecordBytes << " bytes) to "
            << path << "\n";
}

struct JobsOptions {
  uint32_t root = 0;
  std::string out;
  std::string rays;
  uint32_t modelAddress = 0;
  std::string rayType = "primary";
  std::string svo;
  RayWorkloadOptions workload;
};

// The ray records of `--ray-type`: a secondary type traces the camera's frame on the golden model
// over the image of --svo first.
std::vector<RayRecord> workloadRays(const JobsOptions& options, const RunConfig& settings) {
  const GoldenConfig& golden = settings.rtu.coreConfig<SvoKind>();
  const RayType type = parseRayType(options.rayType);
  const RayWorkloadSpec spec = options.workload.resolve(type, golden);
  if (options.svo.empty()) {
    if (type != RayType::Primary)
      throw std::invalid_argument("--ray-type " + options.rayType +
                                  " traces the frame first: give --svo (an image with the model "
                                  "header at --model-address, build --model-header)");
    std::vector<RayRecord> rays = makeFrameRayRecords(settings.camera, options.modelAddress);
    orderRays(rays, spec.order, spec.secondary.seed);
    return rays;
  }
  const SvoImage image = readSvoFile(options.svo);
  const RayWorkload workload =
      makeRayWorkload(image.memory(), options.modelAddress, settings.camera, golden, spec);
  if (type != RayType::Primary && type != RayType::Random)
    std::cout << workload.primaryHits << " primary hits of " << settings.camera.pixelCount()
              << " pixels spawn " << workload.rays.size() << " " << options.rayType << " rays\n";
  return workload.rays;
}

}  // namespace

void addJobsCommand(CLI::App& app) {
  auto options = std::make_shared<JobsOptions>();
  CLI::App* command = app.add_subcommand(
      "jobs", "write one frame's primary rays as host job records (thesis driver format) or as "
              "ray records for an animated model, or its secondary rays (--ray-type)");
  auto request = addConfigOptions(*command, kUseCamera | kUseArithmetic);
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
  command
      ->add_option("--ray-type", options->rayType,
                   "rays to write: primary, shadow, ao, reflection, diffuse or random "
                   "(docs/workloads.md)")
      ->capture_default_str()
      ->needs(rays);
  command->add_option("--svo", options->svo,
                      "SVO image with the model header at --model-address: the frame traced for "
                      "secondary rays, and the box of random rays");
  addRayWorkloadOptions(*command, options->workload, "--seed");
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
      const std::vector<RayRecord> records = workloadRays(*options, configuration.values());
      writeRayBuffer(options->rays, records);
      reportWritten(records.size(), "ray records", options->rays);
    }
  });
}

}  // namespace rtu
