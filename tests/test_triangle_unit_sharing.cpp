// Ray/triangle units shared by groups of cores (core.triangle.shared_by; docs/cycle-semantics.md,
// "Shared triangle units"): the arbiter's round-robin rule by hand, two cores contending for one
// unit worked out cycle by cycle, and the refusal of impossible group sizes. The equivalence of
// the cycle-accurate model with the per-cycle reference under sharing is in
// test_rtu_equivalence.cpp, its results against golden in test_rtu_configurations.cpp.

#include <catch2/catch.hpp>

#include <stdexcept>
#include <utility>
#include <vector>

#include "kind_fixture.h"
#include "kinds/bvh/bvh_image.h"
#include "kinds/bvh/bvh_kind.h"
#include "kinds/bvh/bvh_model.h"
#include "kinds/bvh/langr_builder.h"
#include "reference/rtl_cycle_model.h"
#include "run/rtu_simulation.h"
#include "sim/ca/triangle_unit_arbiter.h"

namespace rtu {
namespace {

using Deferred = std::vector<std::pair<int, uint64_t>>;

TEST_CASE("Triangle unit arbiter: one grant a unit per interval\\, round-robin in its group",
          "[triangle_unit]") {
  // 6 cores, 4 a unit: unit 0 serves cores 0-3, unit 1 cores 4-5; an interval of 3.
  TriangleUnitArbiter units(6, 4, 3);
  std::vector<int> granted;
  Deferred deferred;
  // Cycle 10: cores 1, 2 (unit 0) and 5 (unit 1) ask. Unit 0's turn starts at core 0: core 1
  // wins, core 2 waits for cycle 13; unit 1 grants core 5.
  units.arbitrate(10, {1, 2, 5}, granted, deferred);
  CHECK(granted == std::vector<int>{1, 5});
  CHECK(deferred == Deferred{{2, 13}});
  // Cycle 12: core 0 asks; unit 0 is busy until 13.
  units.arbitrate(12, {0}, granted, deferred);
  CHECK(granted.empty());
  CHECK(deferred == Deferred{{0, 13}});
  // Cycle 13: cores 0 and 2 wait; the turn is core 2's (after core 1): core 2, then core 0 at 16.
  units.arbitrate(13, {0, 2}, granted, deferred);
  CHECK(granted == std::vector<int>{2});
  CHECK(deferred == Deferred{{0, 16}});
  // Cycle 16: cores 0 and 3 ask; the turn is core 3's: core 3, core 0 once more deferred to 19.
  units.arbitrate(16, {0, 3}, granted, deferred);
  CHECK(granted == std::vector<int>{3});
  CHECK(deferred == Deferred{{0, 19}});
  // Cycle 19: after core 3 the turn wraps to core 0 (the group's first).
  units.arbitrate(19, {0, 1}, granted, deferred);
  CHECK(granted == std::vector<int>{0});
  CHECK(deferred == Deferred{{1, 22}});
  // Unit 1, last granted core 5: its turn wraps to core 4; both ask at 13, core 4 wins.
  units.arbitrate(13, {4, 5}, granted, deferred);
  CHECK(granted == std::vector<int>{4});
  CHECK(deferred == Deferred{{5, 16}});
}

// A BVH of two triangles, one behind the other across the z axis, built by langr into a root leaf
// (below 10 triangles), and a ray along z through both, from `rays` records.
struct TwoTriangleScene {
  std::vector<uint32_t> words;
  std::vector<HostRecord> records;
};

TwoTriangleScene twoTriangles(int rays) {
  TriangleMesh mesh;
  mesh.vertices = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, {-1, -1, 1}, {1, -1, 1}, {0, 1, 1}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  TwoTriangleScene scene;
  scene.words = layOut(buildLangr(mesh).tree, mesh).words;
  const uint32_t header = appendBvhModelHeader(scene.words, ModelPlacement{});
  for (int i = 0; i < rays; ++i) {
    RayRecord ray;
    ray.id = static_cast<uint32_t>(i);
    ray.origin = {0.0f, 0.0f, -5.0f};
    ray.direction = {0.0f, 0.0f, 1.0f};
    ray.modelAddress = header;
    scene.records.push_back(ray);
  }
  return scene;
}

TEST_CASE("Two cores sharing one triangle unit: the second core's test waits\\, by hand",
          "[triangle_unit]") {
  // Units: box 1 cycle, triangle latency 6, interval 4. A ray through the root leaf of two
  // triangles, dispatched in D, takes one cycle a state but TEST:
  //   ROOT0 D+1, ROOT1 D+2, ROOT_TEST D+3, REF D+4, TRI0-2 D+5..D+7,
  //   TEST (first, the interval) D+8..D+11, REF D+12, TRI0-2 D+13..D+15,
  //   TEST (the leaf's last, the latency) D+16..D+21, POP D+22, OUT D+23:
  //   cost 3 + 4 + 4 + 4 + 6 + 1 = 22.
  // Core 0 takes ray 0 in D, core 1 ray 1 in D+1 (the job manager's pipeline, one job a cycle).
  // With a unit a core neither waits: OUT in D+23 and D+24.
  // Shared (core.triangle.shared_by = 2): core 0's first test issues in D+8, so the unit is free
  // again from D+12. Core 1 asks in D+9 and waits to D+12 (3 cycles): its first TEST D+12..D+15,
  // REF D+16, TRI0-2 D+17..D+19, last TEST asks in D+20. Core 0's last test asked in D+16, the
  // unit free since D+16 (core 1's grant in D+12 + 4): no wait, the unit free again from D+20,
  // so core 1's last test issues in D+20 at once: D+20..D+25, POP D+26, OUT D+27, its dispatch
  // D+1 plus 1 + 22 + 3 stall cycles. Core 0 is unchanged: OUT in D+23.
  // The result manager buffers a result in its OUT cycle; the host takes core c's in the first
  // cycle after with result_select (the cycle mod 2 cores) = c.
  const TwoTriangleScene scene = twoTriangles(2);
  RtuConfig config = kindConfig<BvhKind<>>();
  config.cores = 2;
  config.coreConfig<BvhKind<>>().cycles = BvhCycles{1, 6, 4};
  const auto hostTakes = [](uint64_t out, int core) {
    uint64_t cycle = out + 1;
    while (cycle % 2 != static_cast<uint64_t>(core)) ++cycle;
    return cycle;
  };
  for (int sharedBy : {1, 2}) {
    INFO("shared by " << sharedBy);
    config.triangleSharedBy = sharedBy;
    const RtlTopRun rtl = runRtlTop(WordMemory(scene.words), scene.records, rtlTopConfig(config));
    const uint64_t d = rtl.dispatchCycles[0];
    REQUIRE(rtl.dispatchCycles[1] == d + 1);
    const int core0 = static_cast<int>(d % 2), core1 = 1 - core0;  // core_select = cycle mod 2
    const uint64_t out0 = d + 23, out1 = d + 1 + 23 + (sharedBy == 2 ? 3 : 0);
    for (const CoreKindResult& result : rtl.results) CHECK(resultCost(result) == 22);
    const std::vector<uint64_t> expected{hostTakes(out0, core0), hostTakes(out1, core1)};
    CHECK(rtl.resultCycles == expected);
    const RtuRun run = simulateRtu(WordMemory(scene.words), scene.records, config);
    checkEqualsRtl(run, rtl);
    CHECK(run.statistics.allCores().unitStallCycles == (sharedBy == 2 ? 3u : 0u));
  }
}

TEST_CASE("core.triangle.shared_by: 1 to the core count\\, for a kind with a triangle unit",
          "[triangle_unit]") {
  RtuConfig config = kindConfig<BvhKind<>>();
  config.cores = 4;
  for (int bad : {0, 5, -1}) {
    config.triangleSharedBy = bad;
    CHECK_THROWS_WITH(validate(config), Catch::Contains("core.triangle.shared_by") &&
                                            Catch::Contains("core count (4)"));
  }
  config.triangleSharedBy = 4;
  CHECK_NOTHROW(validate(config));
  CHECK(config.trianglesShared());
  // The SVO core has no triangle unit: the key has no effect there and is not checked.
  config.core = SvoKind::kName;
  config.triangleSharedBy = 5;
  CHECK_NOTHROW(validate(config));
  CHECK_FALSE(config.trianglesShared());
}

}  // namespace
}  // namespace rtu
