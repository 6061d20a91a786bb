// The cycle-accurate SystemC model against the golden model (per-ray results) and against the
// naive per-cycle transcription of the RTL (total cycles and the cycle of every result), for the
// thesis' t-value records and for ray records against models (ray stages, header fetches), for
// every core kind (tests/kind_fixture.h).

#include <catch2/catch.hpp>

#include "kind_fixture.h"
#include "reference/rtl_cycle_model.h"
#include "run/rtu_simulation.h"

namespace rtu {

TEMPLATE_LIST_TEST_CASE("Thesis configuration: results and every cycle equal the RTL", "[rtu]",
                        TestedKinds) {
  // And with the kind's other settings (for the BVH: states of several cycles).
  using Fixture = KindFixture<TestType>;
  for (const std::string& scene : Fixture::scenes()) {
    const auto s = Fixture::frame(scene, 6, 24, 16);
    for (bool other : {false, true}) {
      for (int cores : {1, 2, 4, 16}) {
        RtuConfig config = kindConfig<TestType>();
        if (other) Fixture::otherArithmetic(config);
        config.cores = cores;
        const RtuRun run = simulateRtu(s.memory(), s.jobs, config);
        const RtlTopRun rtl = runRtlTop(s.memory(), s.jobs, rtlTopConfig(config));
        INFO(scene << ", " << cores << " cores" << (other ? ", other settings" : ""));
        checkEqualsRtl(run, rtl);
      }
    }
  }
}

TEMPLATE_LIST_TEST_CASE("Shared triangle units: results and every cycle equal the RTL", "[rtu]",
                        TestedKinds) {
  // core.triangle.shared_by 2, 4 and all the cores at 4 and 16 cores, with the kind's units'
  // defaults and its other settings (units of several cycles: tests wait, some several turns); a
  // kind without a triangle unit has nothing to share.
  if constexpr (HasTriangleUnit<TestType>::value) {
    using Fixture = KindFixture<TestType>;
    for (const std::string& scene : Fixture::scenes()) {
      const auto s = Fixture::frame(scene, 6, 24, 16);
      for (bool other : {false, true}) {
        for (int cores : {4, 16}) {
          for (int sharedBy : {2, 4, cores}) {
            if (sharedBy == 4 && cores == 4) continue;  // all the cores: once
            RtuConfig config = kindConfig<TestType>();
            if (other) Fixture::otherArithmetic(config);
            config.cores = cores;
            config.triangleSharedBy = sharedBy;
            const RtuRun run = simulateRtu(s.memory(), s.jobs, config);
            const RtlTopRun rtl = runRtlTop(s.memory(), s.jobs, rtlTopConfig(config));
            INFO(scene << ", " << cores << " cores, shared by " << sharedBy
                       << (other ? ", other settings" : ""));
            checkEqualsRtl(run, rtl);
          }
        }
      }
    }
  }
}

TEMPLATE_LIST_TEST_CASE("Ray records: results and every cycle equal the RTL transcription", "[rtu]",
                        TestedKinds) {
  // Each instance's header is fetched at its first ray; the later instances' first rays come
  // while earlier rays wait for cores, so fetches and stalls overlap.
  const auto rays = KindFixture<TestType>::instancedRays();
  for (int cores : {1, 2, 4}) {
    RtuConfig config = kindConfig<TestType>();
    config.cores = cores;
    const RtuRun run = simulateRtu(rays.memory(), rays.records, config);
    const RtlTopRun rtl = runRtlTop(rays.memory(), rays.records, rtlTopConfig(config));
    INFO(cores << " cores");
    checkEqualsRtl(run, rtl);
  }
}

}  // namespace rtu
