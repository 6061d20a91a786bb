#include "app/ray_workload_options.h"

#include <cmath>

namespace rtu {

RayWorkloadSpec RayWorkloadOptions::resolve(RayType type, const GoldenConfig& golden) const {
  RayWorkloadSpec resolved = spec;
  resolved.secondary.type = type;
  resolved.order = parseRayOrder(order);
  if (!lights.empty()) resolved.secondary.lights.clear();
  for (const std::string& light : lights)
    resolved.secondary.lights.push_back(parseLight(light, "--light"));
  golden.validate();
  // The golden hit's t is within a few steps of the format: 16 steps off the surface.
  resolved.secondary.selfOffset = std::ldexp(16.0, -golden.format.fractionBits);
  resolved.secondary.validate();
  return resolved;
}

void addRayWorkloadOptions(CLI::App& command, RayWorkloadOptions& options,
                           const std::string& seedFlag) {
  command.add_option("--light", options.lights,
                     "shadow rays: a light in world space, a point x,y,z, a rectangle "
                     "rect:cx,cy,cz:ux,uy,uz:vx,vy,vz or a disc disc:cx,cy,cz:nx,ny,nz:r "
                     "(repeat for more; default 2.25,4,-2, along the shaded image's light)");
  command
      .add_option("--light-samples", options.spec.secondary.lightSamples,
                  "shadow: rays per primary hit to each area light")
      ->capture_default_str();
  command
      .add_option("--samples", options.spec.secondary.samples,
                  "ao and diffuse: rays per primary hit")
      ->capture_default_str();
  command
      .add_option("--ao-distance", options.spec.secondary.aoDistance,
                  "ao: the occlusion rays' length, world units")
      ->capture_default_str();
  command.add_option("--random-rays", options.spec.randomRays,
                     "random: how many rays (default: one per pixel)");
  command
      .add_option(seedFlag, options.spec.secondary.seed,
                  "seed of the sampled directions, random rays and the shuffled order")
      ->capture_default_str();
  command
      .add_option("--order", options.order,
                  "ray record order: pixel (as generated), shuffled, or sorted (direction "
                  "octant, then origin on a Morton curve)")
      ->capture_default_str();
}

}  // namespace rtu
