#include "inputs/ray_workload.h"

#include "kinds/svo/golden_model.h"

namespace rtu {

namespace {

RayWorkload unordered(const WordMemory& memory, uint32_t modelAddress, const Camera& camera,
                      const GoldenConfig& golden, const RayWorkloadSpec& spec) {
  const RayType type = spec.secondary.type;
  const ModelHeader header = readModelHeader(memory, modelAddress);
  RayWorkload workload;
  if (type == RayType::Random) {
    const size_t count = spec.randomRays == 0 ? camera.pixelCount() : spec.randomRays;
    workload.rays = randomRays(count, header, spec.secondary.seed, modelAddress);
    return workload;
  }
  const std::vector<RayRecord> primaries = makeFrameRayRecords(camera, modelAddress);
  if (type == RayType::Primary) {
    workload.rays = primaries;
    return workload;
  }
  spec.secondary.validate();
  GoldenModel model(memory, golden);
  const std::vector<SurfaceHit> hits =
      surfaceHits(primaries, model.traceRays(primaries, golden.epsilon), header, golden.format);
  workload.primaryHits = hits.size();
  workload.rays = spawnSecondaryRays(hits, spec.secondary, modelAddress);
  return workload;
}

}  // namespace

RayWorkload makeRayWorkload(const WordMemory& memory, uint32_t modelAddress, const Camera& camera,
                            const GoldenConfig& golden, const RayWorkloadSpec& spec) {
  RayWorkload workload = unordered(memory, modelAddress, camera, golden, spec);
  orderRays(workload.rays, spec.order, spec.secondary.seed);
  return workload;
}

}  // namespace rtu
