// Rays with spans (rtu/ray_span.h) through every core kind (tests/kind_fixture.h): the frame's
// primary rays moved into the model (span_records.h), every third an any-hit ray over one unit,
// every third a ray taking the nearest hit ahead, the rest lines. Every model traces them as the
// golden model does, every cycle as the per-cycle RTL reference, and an any-hit ray answers what
// the nearest hit ahead answers within t <= 1.

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "kind_fixture.h"
#include "run/analytic_run.h"
#include "run/lt_simulation.h"
#include "run/rtu_simulation.h"
#include "span_records.h"

namespace rtu {
namespace {

RaySpan spanOf(size_t i) {
  switch (i % 3) {
    case 0: return RaySpan::AnyHit;
    case 1: return RaySpan::Ahead;
    default: return RaySpan::Line;
  }
}

template <class Kind>
struct SpanFrame {
  typename KindFixture<Kind>::Frame frame;
  std::vector<HostRecord> records;
};

template <class Kind>
SpanFrame<Kind> spanFrame(const std::string& scene, int width, int height) {
  SpanFrame<Kind> s{KindFixture<Kind>::frame(scene, 6, width, height), {}};
  s.records = movedIntoModel(KindFixture<Kind>::rayRecords(s.frame, width, height), spanOf);
  return s;
}

size_t anyHitCount(const std::vector<CoreKindResult>& results) {
  size_t count = 0;
  for (const CoreKindResult& result : results) count += (resultIdWord(result) & kAnyHitBit) != 0;
  return count;
}

}  // namespace

TEMPLATE_LIST_TEST_CASE("Span rays: every model's results equal golden's and every cycle the RTL's",
                        "[spans]", TestedKinds) {
  using Fixture = KindFixture<TestType>;
  for (const std::string& scene : Fixture::scenes()) {
    const auto s = spanFrame<TestType>(scene, 24, 16);
    const WordMemory memory = s.frame.memory();
    for (bool other : {false, true}) {
      RtuConfig config = kindConfig<TestType>();
      if (other) Fixture::otherArithmetic(config);
      const std::vector<CoreKindResult> golden = traceGolden(memory, s.records, config);
      REQUIRE(anyHitCount(golden) == (s.records.size() + 2) / 3);
      for (int cores : {1, 4}) {
        INFO(scene << ", " << cores << " cores" << (other ? ", other settings" : ""));
        config.cores = cores;
        config.memory.ideal = true;
        const RtuRun run = simulateRtu(memory, s.records, config);
        CHECK(resultsInJobOrder(run) == golden);
        checkEqualsRtl(run, runRtlTop(memory, s.records, rtlTopConfig(config)));
        const RtuRun analytic = runAnalytic(memory, s.records, config);
        CHECK(analytic.totalCycles == run.totalCycles);
        CHECK(analytic.results == run.results);
        // The kind's counters count the any-hit rays (svo: any_hit_rays; bvh: bvh_any_hit_rays).
        const std::string json = run.statistics.toJson().dump();
        CHECK(json.find("any_hit_rays\":" + std::to_string(anyHitCount(golden))) !=
              std::string::npos);
        config.memory.ideal = false;
        CHECK(resultsInJobOrder(runLooselyTimed(memory, s.records, config)) == golden);
        CHECK(resultsInJobOrder(simulateRtu(memory, s.records, config)) == golden);
      }
    }
  }
}

TEMPLATE_LIST_TEST_CASE("An any-hit ray answers what the nearest hit ahead answers within t <= 1",
                        "[spans]", TestedKinds) {
  using Fixture = KindFixture<TestType>;
  const RtuConfig config = kindConfig<TestType>();
  for (const std::string& scene : Fixture::scenes()) {
    auto frame = Fixture::frame(scene, 6, 64, 48);
    const std::vector<HostRecord> primaries = Fixture::rayRecords(frame, 64, 48);
    const auto anyHit =
        traceGolden(frame.memory(), movedIntoModel(primaries, RaySpan::AnyHit), config);
    const auto ahead =
        traceGolden(frame.memory(), movedIntoModel(primaries, RaySpan::Ahead), config);
    int occluded = 0, open = 0;
    for (size_t i = 0; i < primaries.size(); ++i) {
      const double t = resultHit(ahead[i]) ? hitDistance(ahead[i], config.coreConfigs) : INFINITY;
      // Within the format's rounding of the segment's end, either answer is right.
      if (std::abs(t - 1) < 1e-4) continue;
      INFO(scene << ", ray " << i << ", nearest hit ahead at t = " << t);
      REQUIRE(resultHit(anyHit[i]) == (t <= 1));
      ++(t <= 1 ? occluded : open);
    }
    INFO(scene << ": " << occluded << " occluded, " << open << " open");
    CHECK(occluded > 100);
    CHECK(open > 100);
  }
}

}  // namespace rtu
