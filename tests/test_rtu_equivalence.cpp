// The cycle-accurate SystemC model against the golden model (per-ray results) and against the
// naive per-cycle transcription of the RTL (total cycles and the cycle of every result), for the
// thesis' t-value records and for ray records against models (ray stages, header fetches).

#include <catch2/catch.hpp>

#include "inputs/camera.h"
#include "kinds/svo/golden_model.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"
#include "reference/rtl_cycle_model.h"
#include "run/rtu_simulation.h"
#include "three_balls_scene.h"

namespace rtu {
namespace {

struct SceneJobs {
  SvoBuild build;
  std::vector<TraversalJob> jobs;
};

SceneJobs smallFrame(const std::string& scene, int width, int height) {
  SceneJobs s{buildSvo(*makeProceduralScene(scene, 6)), {}};
  Camera camera;
  camera.width = width;
  camera.height = height;
  s.jobs = makeFrameJobs(camera, s.build.image.root);
  return s;
}

}  // namespace

TEST_CASE("Thesis configuration: results and every cycle equal the RTL", "[rtu]") {
  const auto scene = GENERATE(as<std::string>{}, "sphere", "menger", "terrain", "noise");
  const int cores = GENERATE(1, 2, 4, 16);
  const SceneJobs s = smallFrame(scene, 24, 16);
  RtuConfig config;
  config.cores = cores;
  const RtuRun run = simulateRtu(s.build.image.memory(), s.jobs, config);
  const RtlTopRun rtl =
      runRtlTop(s.build.image.memory(), s.jobs, RtlTopConfig{cores, config.golden()});
  INFO(scene << ", " << cores << " cores");
  CHECK(run.totalCycles == rtl.totalCycles);
  CHECK(run.arrivalCycles == rtl.resultCycles);
  CHECK(run.results == rtl.results);
}

TEST_CASE("Ray records: results and every cycle equal the RTL transcription", "[rtu]") {
  // Each instance's header is fetched at its first ray; the later instances' first rays come
  // while earlier rays wait for cores, so fetches and stalls overlap.
  const ThreeBalls scene;
  const int cores = GENERATE(1, 2, 4);
  std::vector<HostRecord> records;
  const std::vector<RayRecord> rays = frameRays(16, 10);
  for (size_t i = 0; i < rays.size(); ++i) {
    RayRecord record = rays[i];
    record.modelAddress = scene.instances[std::min<size_t>(i / 40, 2)].headerAddress;
    records.push_back(record);
  }
  RtuConfig config;
  config.cores = cores;
  const RtuRun run = simulateRtu(scene.memory.memory(), records, config);
  const RtlTopRun rtl = runRtlTop(scene.memory.memory(), records,
                                  RtlTopConfig{cores, config.golden(), config.jobManager.rayStages,
                                               config.jobManager.headerFetchCycles});
  INFO(cores << " cores");
  CHECK(run.totalCycles == rtl.totalCycles);
  CHECK(run.arrivalCycles == rtl.resultCycles);
  CHECK(run.results == rtl.results);
}

}  // namespace rtu
