#pragma once
// What the tests need of a core kind. The equivalence tests (the golden model against the
// cycle-accurate, loosely-timed and analytic runs and the per-cycle RTL reference) and the oracle
// test are TEMPLATE_LIST_TEST_CASEs over TestedKinds, every kind of the registry, so a new kind
// inherits them by specialising KindFixture in tests/kinds/<name>_fixture.h (included below).
// tests/kinds/svo_fixture.h is the worked example; a kind's fixture declares:
//   Frame                  a test scene's image and a frame of host records on it: memory(), jobs
//   scenes()               the names of its test scenes
//   frame(scene, detail, width, height)   a frame of primary rays on a scene built to a detail
//   rayRecords(frame, width, height)      the frame's rays as ray records against a model of it
//   instancedRays()        memory() and records against several models (header fetches overlap)
//   golden(memory, config, jobs)          its golden model's results, as a run's (CoreKindResult)
//   firstDispatch(timing)  the cycle a frame's first job, accepted in cycle 0, leaves the job
//                          manager's pipeline, derived by hand from the job manager's timing
//   otherArithmetic(config)               settings of its own other than the thesis', for which
//                                         every model must still agree
//   checkOracle()          its independent oracle against its golden model (architecture.md,
//                          "Independent oracles")

#include <catch2/catch.hpp>

#include "inputs/camera.h"
#include "kinds/core_result.h"
#include "kinds/registry.h"
#include "reference/rtl_cycle_model.h"
#include "rtu/golden_shell.h"
#include "sim/rtu_config.h"

namespace rtu {

template <class Kind>
struct KindFixture;

using TestedKinds = CoreKinds::Tuple;

// The thesis configuration with cores of `Kind`.
template <class Kind>
RtuConfig kindConfig() {
  RtuConfig config;
  config.core = Kind::kName;
  return config;
}

// The default camera at a fixture frame's size (every kind's frames look at the same view).
inline Camera fixtureCamera(int width, int height) {
  Camera camera;
  camera.width = width;
  camera.height = height;
  return camera;
}

// A ray-record kind's golden results (the triangle kinds' fixtures): its job set-up, then its
// traversal to the end under the untimed shell.
template <class Kind>
std::vector<CoreKindResult> goldenBehindSetup(const WordMemory& memory, const RtuConfig& config,
                                              const std::vector<HostRecord>& jobs) {
  const typename Kind::Config& own = config.coreConfig<Kind>();
  typename Kind::Setup setup(memory, config.jobManager, own);
  GoldenShell<Kind> shell(memory, own);
  std::vector<CoreKindResult> results;
  for (const HostRecord& record : jobs) {
    const auto set = setUpHostRecord<Kind>(setup, record);
    typename Kind::Result result;
    shell.run(set.idWord, set.job, result);
    results.emplace_back(result);
  }
  return results;
}

// A ray record passes the P_STAGES registers and the ray stages (the move into the model's
// space and the kind's conversion), and the first against a model waits for its model header
// and its image's header, 16 words each (rtu/ray_models.h).
inline uint64_t rayRecordFirstDispatch(const JobManagerTiming& timing) {
  return static_cast<uint64_t>(timing.stages + timing.rayStages + 2 * timing.headerFetchCycles);
}

// The per-cycle RTL reference of the RTU `config` describes.
inline RtlTopConfig rtlTopConfig(const RtuConfig& config) {
  return RtlTopConfig{config.cores, config.coreConfigs, config.jobManager.rayStages,
                      config.jobManager.headerFetchCycles, config.core};
}

// A run's results and every cycle against the RTL transcription's (run: RtuRun, the SystemC
// model's or the analytic run's).
template <class Run>
void checkEqualsRtl(const Run& run, const RtlTopRun& rtl) {
  CHECK(run.totalCycles == rtl.totalCycles);
  CHECK(run.arrivalCycles == rtl.resultCycles);
  CHECK(run.results == rtl.results);
}

}  // namespace rtu

#include "kinds/bih_fixture.h"
#include "kinds/bvh_fixture.h"
#include "kinds/kd_fixture.h"
#include "kinds/svo_fixture.h"
