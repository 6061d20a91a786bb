#include "inputs/ray_workload.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "kinds/svo/golden_model.h"

namespace rtu {

namespace {

RayWorkload spawnUnordered(const std::vector<SurfaceHit>& hits, const ModelHeader& box,
                           size_t pixels, uint32_t modelAddress, const RayWorkloadSpec& spec) {
  RayWorkload workload;
  if (spec.secondary.type == RayType::Random) {
    const size_t count = spec.randomRays == 0 ? pixels : spec.randomRays;
    workload.rays = randomRays(count, box, spec.secondary.seed, modelAddress);
    return workload;
  }
  workload.primaryHits = hits.size();
  workload.rays = spawnSecondaryRays(hits, spec.secondary, modelAddress);
  return workload;
}

RayWorkload unordered(const WordMemory& memory, uint32_t modelAddress, const Camera& camera,
                      const GoldenConfig& golden, const RayWorkloadSpec& spec) {
  const RayType type = spec.secondary.type;
  const ModelHeader header = readModelHeader(memory, modelAddress);
  const std::vector<RayRecord> primaries = makeFrameRayRecords(camera, modelAddress);
  RayWorkload workload;
  if (type == RayType::Primary) {
    workload.rays = primaries;
    return workload;
  }
  std::vector<SurfaceHit> hits;
  if (type != RayType::Random) {
    spec.secondary.validate();
    GoldenModel model(memory, golden);
    hits =
        surfaceHits(primaries, model.traceRays(primaries, golden.epsilon), header, golden.format);
  }
  return spawnUnordered(hits, header, camera.pixelCount(), modelAddress, spec);
}

}  // namespace

std::vector<RayType> parseRayPasses(const std::string& text, const std::string& option) {
  std::vector<RayType> passes;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = std::min(text.find_first_of(",+", start), text.size());
    const std::string name = text.substr(start, comma - start);
    RayType type;
    try {
      type = parseRayType(name);
    } catch (const std::invalid_argument&) {
      throw std::invalid_argument(
          option + " " + text + ": '" + name +
          "' is not one of primary, shadow, ao, reflection, diffuse, random");
    }
    for (RayType seen : passes)
      if (seen == type)
        throw std::invalid_argument(option + " " + text + ": " + toString(type) + " twice");
    passes.push_back(type);
    start = comma + 1;
  }
  if (passes.front() != RayType::Primary)
    throw std::invalid_argument(option + " " + text +
                                ": the first pass is primary (the others spawn from its hits)");
  return passes;
}

RayWorkload makeRayWorkload(const WordMemory& memory, uint32_t modelAddress, const Camera& camera,
                            const GoldenConfig& golden, const RayWorkloadSpec& spec) {
  RayWorkload workload = unordered(memory, modelAddress, camera, golden, spec);
  orderRays(workload.rays, spec.order, spec.secondary.seed);
  return workload;
}

RayWorkload spawnRayWorkload(const std::vector<SurfaceHit>& hits, const ModelHeader& box,
                             size_t pixels, uint32_t modelAddress, const RayWorkloadSpec& spec) {
  if (spec.secondary.type == RayType::Primary)
    throw std::invalid_argument("spawnRayWorkload: primary rays are the frame's, not spawned");
  RayWorkload workload = spawnUnordered(hits, box, pixels, modelAddress, spec);
  orderRays(workload.rays, spec.order, spec.secondary.seed);
  return workload;
}

}  // namespace rtu
