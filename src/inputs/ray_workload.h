#pragma once
// One workload of ray records of a single type (issue 32, `rtusim jobs --ray-type`): a camera
// frame's primary rays, or the secondary rays spawned from the golden model's hits of that frame
// (inputs/secondary_rays.h), or random rays in the model's box, in the order asked for
// (inputs/ray_order.h).

#include <cstdint>
#include <string>
#include <vector>

#include "inputs/camera.h"
#include "inputs/ray_order.h"
#include "inputs/secondary_rays.h"
#include "kinds/svo/golden_config.h"
#include "rtu/word_memory.h"

namespace rtu {

// "primary,shadow,ao" (or "primary+shadow+ao", which a sweep's --grid list can hold): the first
// pass must be primary, then shadow, ao, reflection, diffuse or random, each at most once.
// Throws std::invalid_argument naming `option`.
std::vector<RayType> parseRayPasses(const std::string& text, const std::string& option);

struct RayWorkloadSpec {
  SecondarySettings secondary;  // its type is the workload's
  RayOrder order = RayOrder::Pixel;
  size_t randomRays = 0;  // random: how many (0: one per pixel)
};

struct RayWorkload {
  std::vector<RayRecord> rays;
  size_t primaryHits = 0;  // the frame's, for secondary types
};

// The workload on the model whose header is at `modelAddress` in `memory`. Throws
// std::runtime_error for a header that is not valid, std::invalid_argument for settings that are
// not (SecondarySettings::validate).
RayWorkload makeRayWorkload(const WordMemory& memory, uint32_t modelAddress, const Camera& camera,
                            const GoldenConfig& golden, const RayWorkloadSpec& spec);

// A secondary workload (spec's type not primary) spawned from `hits`, a frame's primary hits in
// pixel order, by any kind's golden model: random rays fill the cube that `box` places (one per
// pixel of the frame's `pixels` unless spec.randomRays says), every record points at the model
// header at `modelAddress`; ordered as spec.order says.
RayWorkload spawnRayWorkload(const std::vector<SurfaceHit>& hits, const ModelHeader& box,
                             size_t pixels, uint32_t modelAddress, const RayWorkloadSpec& spec);

}  // namespace rtu
