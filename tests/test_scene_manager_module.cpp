// The cycle-accurate scene manager (src/sim/ca/scene_manager_module.h) inside the SystemC RTU,
// against the untimed golden scene manager: per ray the same nearest hit and summed cost, over
// the frame the same jobs, culled instances and early terminations, for any queue sizes, core
// count, latency and with or without a reorder buffer.
#include <catch2/catch.hpp>

#include "kinds/core_result.h"
#include "run/rtu_simulation.h"
#include "scene/scene_manager.h"
#include "three_balls_scene.h"

namespace rtu {

TEST_CASE(
    "Scene manager module: the golden scene manager's hits, jobs, culling and early terminations",
    "[scene]") {
  const ThreeBalls scene;
  const std::vector<RayRecord> rays = frameRays(24, 16);
  SceneManager golden(scene.memory.memory(), GoldenConfig{}, scene.instances);
  std::vector<SceneHit> expected;
  uint64_t jobs = 0, culled = 0, early = 0, skipped = 0;
  for (const RayRecord& ray : rays) {
    expected.push_back(golden.trace(ray));
    jobs += expected.back().jobs;
    culled += expected.back().culled;
    early += expected.back().skipped > 0;
    skipped += expected.back().skipped;
  }
  REQUIRE(culled > 0);  // the scene exercises both
  REQUIRE(early > 0);

  const auto [cores, raysInFlight, jobsOutstanding, latency, reorder] =
      GENERATE(std::make_tuple(1, 1, 1, 0, 0), std::make_tuple(4, 8, 8, 2, 0),
               std::make_tuple(4, 8, 3, 5, 4), std::make_tuple(1, 3, 8, 1, 2),
               std::make_tuple(16, 32, 32, 2, 0));
  RtuConfig config;
  config.cores = cores;
  config.sceneManager.raysInFlight = raysInFlight;
  config.sceneManager.jobsOutstanding = jobsOutstanding;
  config.sceneManager.latency = latency;
  config.reorderCapacity = reorder;
  CAPTURE(cores, raysInFlight, jobsOutstanding, latency, reorder);
  const RtuRun run = simulateScene(scene.memory.memory(), rays, scene.instances, config);
  REQUIRE(run.results.size() == rays.size());
  for (size_t i = 0; i < run.results.size(); ++i) {
    const SceneHit& want = expected[run.jobIndices[i]];
    const TraversalResult& got = svoResult(run.results[i]);
    const TraversalResult& wanted = svoResult(want.result);
    CAPTURE(run.jobIndices[i]);
    REQUIRE(got.hit == wanted.hit);
    REQUIRE(got.idWord == wanted.idWord);
    REQUIRE(got.cost == wanted.cost);
    if (got.hit) {
      REQUIRE(got.tHit == wanted.tHit);
      REQUIRE(got.normal == wanted.normal);
    }
  }
  REQUIRE(run.statistics.scene.has_value());
  const SceneManagerStatistics& stats = *run.statistics.scene;
  CHECK(stats.rays == rays.size());
  CHECK(stats.jobs == jobs);
  CHECK(stats.culled == culled);
  CHECK(stats.earlyTerminations == early);
  CHECK(stats.skipped == skipped);
}

TEST_CASE("Scene manager module: more rays in flight keep more cores busy", "[scene]") {
  const ThreeBalls scene;
  const std::vector<RayRecord> rays = frameRays(16, 12);
  RtuConfig config;
  config.cores = 8;
  config.sceneManager.raysInFlight = 1;
  const uint64_t one =
      simulateScene(scene.memory.memory(), rays, scene.instances, config).totalCycles;
  config.sceneManager.raysInFlight = 16;
  config.sceneManager.jobsOutstanding = 16;
  const uint64_t many =
      simulateScene(scene.memory.memory(), rays, scene.instances, config).totalCycles;
  CHECK(many * 3 < one);
}

TEST_CASE("Scene manager module: impossible queue sizes are refused by name", "[scene]") {
  RtuConfig config;
  config.sceneManager.raysInFlight = 0;
  CHECK_THROWS_WITH(validate(config), Catch::Contains("scene_manager.rays_in_flight"));
  config = RtuConfig{};
  config.sceneManager.latency = -1;
  CHECK_THROWS_WITH(validate(config), Catch::Contains("scene_manager.latency"));
}

}  // namespace rtu
