#pragma once
// The options of a workload beyond primary rays (issue 32, docs/workloads.md), shared by
// `jobs --ray-type` and `render --passes`: lights, samples, AO distance, random rays, seed, order.

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "inputs/ray_workload.h"
#include "kinds/svo/golden_config.h"

namespace rtu {

struct RayWorkloadOptions {
  std::vector<std::string> lights;
  std::string order = "pixel";
  RayWorkloadSpec spec;

  // The spec of a workload of `type` on a core of `golden`'s format: the lights and order parsed,
  // and the self-intersection offset 16 steps of the format. Throws std::invalid_argument naming
  // the option.
  RayWorkloadSpec resolve(RayType type, const GoldenConfig& golden) const;
};

// Adds --light, --samples, --ao-distance, --random-rays, the seed's flag `seedFlag` and --order.
void addRayWorkloadOptions(CLI::App& command, RayWorkloadOptions& options,
                           const std::string& seedFlag);

}  // namespace rtu
