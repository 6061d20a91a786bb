// The loosely-timed model (sc_model/lt_simulation.h): per-ray results equal the golden model's
// on every scene, core count, memory and policy; its cycles against the cycle-accurate model's on
// small frames, within the bounds docs/fidelity.md states; refusals name the setting.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "camera.h"
#include "golden_model.h"
#include "lt_simulation.h"
#include "model_run.h"
#include "procedural_scenes.h"
#include "svo_builder.h"

namespace rtu {
namespace {

struct Frame {
  SvoBuild build;
  std::vector<TraversalJob> jobs;
};

Frame frame(const std::string& scene, int depth, int width, int height) {
  Frame f{buildSvo(*makeProceduralScene(scene, depth)), {}};
  Camera camera;
  camera.width = width;
  camera.height = height;
  f.jobs = makeFrameJobs(camera, f.build.image.root);
  return f;
}

RtuConfig configWith(int cores, bool cached, SchedulerPolicy policy) {
  RtuConfig config;
  config.cores = cores;
  config.memory.ideal = !cached;
  config.scheduler = policy;
  return config;
}

double relativeError(uint64_t value, uint64_t reference) {
  return std::abs(static_cast<double>(value) / static_cast<double>(reference) - 1);
}

}  // namespace

TEST_CASE("LT: per-ray results equal the golden model's", "[lt]") {
  for (const std::string& scene : proceduralSceneNames()) {
    const Frame f = frame(scene, 6, 48, 32);
    const std::vector<TraversalResult> golden =
        GoldenModel(f.build.image.memory(), RtuConfig{}.golden()).traceAll(f.jobs);
    for (int cores : {1, 4, 16, 64})
      for (bool cached : {false, true})
        for (SchedulerPolicy policy : {SchedulerPolicy::CyclicFirstAvailable,
                                       SchedulerPolicy::FirstAvailable, SchedulerPolicy::RoundRobin}) {
          INFO(scene << ", " << cores << " cores, " << (cached ? "cached" : "ideal") << ", "
                     << toString(policy));
          RtuConfig config = configWith(cores, cached, policy);
          config.ltQuantum = cores == 4 ? 10 : 1000;
          const RtuRun run = runLooselyTimed(f.build.image.memory(), f.jobs, config);
          REQUIRE(resultsInJobOrder(run) == golden);
          CHECK(run.statistics.rays == f.jobs.size());
          CHECK(run.statistics.allCores().jobs == f.jobs.size());
        }
  }
}

TEST_CASE("LT: total cycles near the cycle-accurate model's on small frames", "[lt]") {
  // Bounds measured on these frames (docs/fidelity.md has the full-frame figures): ideal memory
  // within 3 %, cached within 6 %, at a quantum of 100 cycles.
  for (const std::string& scene : {"menger", "terrain"}) {
    const Frame f = frame(scene, 7, 160, 90);
    for (bool cached : {false, true}) {
      RtuConfig config = configWith(16, cached, SchedulerPolicy::CyclicFirstAvailable);
      config.ltQuantum = 100;
      const RtuRun ca = simulateRtu(f.build.image.memory(), f.jobs, config);
      const RtuRun lt = runLooselyTimed(f.build.image.memory(), f.jobs, config);
      INFO(scene << (cached ? " cached" : " ideal") << ": lt " << lt.totalCycles << ", ca "
                 << ca.totalCycles);
      CHECK(relativeError(lt.totalCycles, ca.totalCycles) < (cached ? 0.06 : 0.03));
      if (cached) {
        CHECK(std::abs(hitRate(lt.statistics.allL1()) - hitRate(ca.statistics.allL1())) < 0.05);
        CHECK(lt.statistics.totalBlocked > 0);
      } else {
        CHECK(lt.statistics.totalBlocked == 0);
      }
      CHECK(lt.statistics.model == "lt");
    }
  }
}

TEST_CASE("LT: one core, ideal memory, thesis links: exactly the cycle-accurate cycles", "[lt]") {
  // With one core nothing runs out of order: each job is dispatched at the select counter's
  // first cycle after the core is idle, INIT follows, the result drains at once.
  const Frame f = frame("sphere", 5, 16, 8);
  const RtuConfig config = configWith(1, false, SchedulerPolicy::CyclicFirstAvailable);
  const RtuRun ca = simulateRtu(f.build.image.memory(), f.jobs, config);
  const RtuRun lt = runLooselyTimed(f.build.image.memory(), f.jobs, config);
  CHECK(lt.arrivalCycles == ca.arrivalCycles);
  CHECK(lt.totalCycles == ca.totalCycles);
}

TEST_CASE("LT: settings it cannot model are refused by name", "[lt]") {
  const Frame f = frame("sphere", 4, 8, 8);
  RtuConfig config;
  config.reorderCapacity = 16;
  CHECK_THROWS_WITH(runLooselyTimed(f.build.image.memory(), f.jobs, config),
                    Catch::Contains("reorder"));
  config.reorderCapacity = 0;
  config.hostInput.activeProbability = 0.5;
  CHECK_THROWS_WITH(runLooselyTimed(f.build.image.memory(), f.jobs, config),
                    Catch::Contains("randomly inactive"));
}

TEST_CASE("Model choice: golden times golden costs with ideal memory", "[lt]") {
  const Frame f = frame("menger", 5, 16, 16);
  RtuConfig cached = configWith(4, true, SchedulerPolicy::CyclicFirstAvailable);
  RtuConfig ideal = cached;
  ideal.memory.ideal = true;
  const RtuRun golden = runModel(ModelKind::Golden, f.build.image.memory(), f.jobs, cached);
  const RtuRun ca = runModel(ModelKind::CycleAccurate, f.build.image.memory(), f.jobs, ideal);
  CHECK(golden.statistics.model == "golden");
  CHECK(golden.totalCycles == ca.totalCycles);  // the recurrence is exact with ideal memory
  CHECK(parseModelKind("lt") == ModelKind::LooselyTimed);
  CHECK_THROWS_WITH(parseModelKind("systemc"), Catch::Contains("golden, lt or ca"));
}

}  // namespace rtu
