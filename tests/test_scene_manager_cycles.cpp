// The cycle-accurate scene manager (src/sim/ca/scene_manager_module.h, inside the SystemC RTU)
// against its plain per-cycle reference (src/reference/scene_manager_cycles.h, above the per-cycle
// RTL transcription): every job entering the job manager in the same cycle, the same merged result
// of every ray arriving in the same cycle, the same total cycles and statistics, for several core
// counts and scene manager settings.
#include <catch2/catch.hpp>

#include <map>
#include <tuple>

#include "reference/scene_manager_cycles.h"
#include "run/rtu_simulation.h"
#include "three_balls_scene.h"

namespace rtu {
namespace {

RtlTopConfig rtlConfig(const RtuConfig& config) {
  return RtlTopConfig{config.cores, config.coreConfigs, config.jobManager.rayStages,
                      config.jobManager.headerFetchCycles};
}

void checkEqual(const RtuRun& run, const SceneCyclesRun& reference) {
  REQUIRE(run.statistics.scene.has_value());
  CHECK(run.totalCycles == reference.totalCycles);
  CHECK(run.jobIssueCycles == reference.issueCycles);
  CHECK(run.arrivalCycles == reference.arrivalCycles);
  CHECK(run.jobIndices == reference.rays);
  CHECK(run.results == reference.results);
  CHECK(run.instances == reference.instances);
  CHECK(*run.statistics.scene == reference.statistics);
}

}  // namespace

TEST_CASE("Scene manager module equals the per-cycle reference in every cycle", "[scene][cycles]") {
  const ThreeBalls scene;
  const std::vector<RayRecord> rays = frameRays(20, 12);
  const auto [cores, raysInFlight, jobsOutstanding, latency, cull, early] =
      GENERATE(std::make_tuple(1, 1, 1, 0, true, true), std::make_tuple(4, 8, 8, 2, true, true),
               std::make_tuple(4, 8, 3, 5, true, true), std::make_tuple(2, 3, 8, 1, true, true),
               std::make_tuple(16, 32, 32, 2, true, true), std::make_tuple(4, 6, 4, 0, false, true),
               std::make_tuple(3, 8, 8, 2, true, false));
  RtuConfig config;
  config.cores = cores;
  config.sceneManager.raysInFlight = raysInFlight;
  config.sceneManager.jobsOutstanding = jobsOutstanding;
  config.sceneManager.latency = latency;
  config.sceneManager.options = SceneManagerOptions{cull, early};
  CAPTURE(cores, raysInFlight, jobsOutstanding, latency, cull, early);

  const SceneCyclesRun reference = runSceneCycles(scene.memory.memory(), rays, scene.instances,
                                                  config.sceneManager, rtlConfig(config));
  // The frame exercises what the settings allow: rays through several instances, rays with
  // every instance culled, rays that end early.
  const SceneManagerStatistics& stats = reference.statistics;
  REQUIRE(stats.jobsPerRay.rbegin()->first > 1);
  if (cull) REQUIRE(stats.jobsPerRay.count(0) == 1);
  if (early) REQUIRE(stats.earlyTerminations > 0);
  checkEqual(simulateScene(scene.memory.memory(), rays, scene.instances, config), reference);
}

TEST_CASE("Scene manager module equals the per-cycle reference with other job manager latencies",
          "[scene][cycles]") {
  const ThreeBalls scene;
  const std::vector<RayRecord> rays = frameRays(12, 8);
  const auto [rayStages, headerFetch] = GENERATE(std::make_tuple(0, 0), std::make_tuple(3, 40));
  RtuConfig config;
  config.cores = 4;
  config.sceneManager.raysInFlight = 6;
  config.jobManager.rayStages = rayStages;
  config.jobManager.headerFetchCycles = headerFetch;
  CAPTURE(rayStages, headerFetch);
  checkEqual(simulateScene(scene.memory.memory(), rays, scene.instances, config),
             runSceneCycles(scene.memory.memory(), rays, scene.instances, config.sceneManager,
                            rtlConfig(config)));
}

TEST_CASE("Rays that miss every instance leave `latency` cycles after they entered",
          "[scene][cycles]") {
  // Worked out from the rules: ray i is offered from the cycle after ray i - 1 was taken. With
  // room for every ray, ray i is taken in i, done and handed to the host in i + latency. With one
  // ray in flight, ray i is taken in the cycle after ray i - 1 left: i (latency + 1), and leaves
  // latency cycles later.
  const ThreeBalls scene;
  std::vector<RayRecord> away;  // from behind the balls, looking away from them
  for (uint32_t id = 0; id < 6; ++id)
    away.push_back(makeRayRecord(id, Ray{{0.1 * id, 0.0, -3.5}, {0.0, 0.2, -1.0}}, 0));
  const int latency = GENERATE(0, 3);
  const int raysInFlight = GENERATE(1, 8);
  RtuConfig config;
  config.cores = 2;
  config.sceneManager.latency = latency;
  config.sceneManager.raysInFlight = raysInFlight;
  CAPTURE(latency, raysInFlight);
  const SceneCyclesRun reference = runSceneCycles(scene.memory.memory(), away, scene.instances,
                                                  config.sceneManager, rtlConfig(config));
  std::vector<uint64_t> expected;
  for (uint64_t i = 0; i < away.size(); ++i)
    expected.push_back((raysInFlight == 1 ? i * (latency + 1) : i) + latency);
  CHECK(reference.arrivalCycles == expected);
  CHECK(reference.statistics.jobsPerRay == std::map<uint64_t, uint64_t>{{0, away.size()}});
  CHECK(reference.statistics.culled == away.size() * scene.instances.size());
  checkEqual(simulateScene(scene.memory.memory(), away, scene.instances, config), reference);
}

}  // namespace rtu
