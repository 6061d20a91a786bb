// Sampled simulation (src/run/sampled_run.h): the plan's blocks, the interval arithmetic, the
// statistics of a window, and the estimate against a full cycle-accurate run.

#include <catch2/catch.hpp>

#include <cmath>

#include "inputs/camera.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"
#include "run/sampled_run.h"
#include "run/statistics_window.h"

namespace rtu {
namespace {

struct CachedFrame {
  SvoImage image;
  std::vector<HostRecord> jobs;
  RtuConfig config;
};

// A menger frame of `width` x `height` rays on `cores` cores with the default caches.
CachedFrame cachedFrame(int depth, int width, int height, int cores) {
  CachedFrame frame{buildSvo(*makeProceduralScene("menger", depth)).image, {}, {}};
  Camera camera;
  camera.width = width;
  camera.height = height;
  const std::vector<TValueRecord> jobs = makeFrameJobs(camera, frame.image.root);
  frame.jobs.assign(jobs.begin(), jobs.end());
  frame.config.cores = cores;
  frame.config.memory.ideal = false;
  return frame;
}

}  // namespace

TEST_CASE("Sample plan: strata tile the middle, two distinct blocks in each", "[sampling]") {
  SampleSpec spec;
  spec.fraction = 0.1;
  spec.seed = 7;
  const uint64_t rays = 1920 * 1080;
  const SamplePlan plan = planSample(rays, 16, spec);
  const uint64_t block = plan.blockRays;
  REQUIRE(plan.strata.size() >= 2);
  CHECK(plan.warmupRays == 512);
  CHECK(plan.cooldownRays == 48);
  CHECK(plan.simulatedRays() <= rays / 10);
  uint64_t next = block;  // the head block comes first
  for (const SamplePlan::Stratum& stratum : plan.strata) {
    CHECK(stratum.first == next);
    next = stratum.first + stratum.rays;
    REQUIRE(stratum.blocks.size() == 2);
    CHECK(stratum.blocks[0] != stratum.blocks[1]);
    for (uint64_t first : stratum.blocks) {
      CHECK((first - stratum.first) % block == 0);
      CHECK(first + block <= stratum.first + stratum.rays);
    }
  }
  CHECK(next == plan.tailFirst);
  CHECK(plan.tailFirst == rays - block);
}

TEST_CASE("Sample plan: another seed, other blocks, too small a fraction is refused",
          "[sampling]") {
  SampleSpec spec;
  spec.fraction = 0.1;
  const SamplePlan a = planSample(1000000, 4, spec);
  spec.seed = 2;
  const SamplePlan b = planSample(1000000, 4, spec);
  bool differ = false;
  for (size_t h = 0; h < a.strata.size(); ++h) differ |= a.strata[h].blocks != b.strata[h].blocks;
  CHECK(differ);
  spec.fraction = 0.001;
  CHECK_THROWS_WITH(planSample(1000000, 4, spec), Catch::Contains("sample.fraction"));
  spec.fraction = 1.5;
  CHECK_THROWS_WITH(planSample(1000000, 4, spec), Catch::Contains("sample.fraction"));
}

TEST_CASE("Student's t quantiles against the table", "[sampling]") {
  // Tabulated two-sided 95 % values.
  CHECK(studentT975(3) == Approx(3.182).epsilon(0.01));
  CHECK(studentT975(10) == Approx(2.228).epsilon(0.001));
  CHECK(studentT975(30) == Approx(2.042).epsilon(0.001));
  CHECK(studentT975(100000) == Approx(1.960).epsilon(0.001));
}

TEST_CASE("Statistics after a prefix: counters subtracted, window's rays and cycles",
          "[sampling]") {
  RtuStatistics whole, prefix;
  whole.coreTimes.resize(2);
  prefix.coreTimes.resize(2);
  whole.coreTimes[1].busyCycles = 100;
  prefix.coreTimes[1].busyCycles = 30;
  whole.l1 = {CacheStats{50, 40, 2, 8, 1}, CacheStats{}};
  prefix.l1 = {CacheStats{20, 15, 1, 4, 0}, CacheStats{}};
  whole.waitHistogram = {{0, 10}, {3, 2}};
  prefix.waitHistogram = {{0, 4}, {3, 2}};
  whole.totalCost = 500;
  prefix.totalCost = 120;
  const RtuStatistics part = statisticsAfter(whole, prefix, 12, 40);
  CHECK(part.rays == 12);
  CHECK(part.totalCycles == 40);
  CHECK(part.coreTimes[1].busyCycles == 70);
  CHECK(part.l1[0].accesses == 30);
  CHECK(part.l1[0].hits == 25);
  CHECK(part.l1[0].misses == 4);
  CHECK(part.waitHistogram == std::map<uint64_t, uint64_t>{{0, 6}});
  CHECK(part.totalCost == 380);

  RtuStatistics total;
  addStatistics(total, part);
  addStatistics(total, part);
  CHECK(total.rays == 24);
  CHECK(total.totalCycles == 80);
  CHECK(total.coreTimes[1].busyCycles == 140);
  CHECK(total.waitHistogram == std::map<uint64_t, uint64_t>{{0, 12}});
}

TEST_CASE("Snapshots do not change the run and fall on their cycles", "[sampling]") {
  const CachedFrame frame = cachedFrame(5, 40, 30, 4);
  const SvoImage& image = frame.image;
  const std::vector<HostRecord>& jobs = frame.jobs;
  const RtuConfig& config = frame.config;
  const RtuRun plain = simulateRtu(image.memory(), jobs, config);
  BlockRun plan;
  plan.afterResults = {100, 700};
  plan.everyCycles = 16;
  const RtuRun sliced = simulateRtu(image.memory(), jobs, config, plan);
  CHECK(sliced.arrivalCycles == plain.arrivalCycles);
  REQUIRE(sliced.snapshots.size() == 2);
  for (size_t i = 0; i < 2; ++i) {
    const RunSnapshot& snapshot = sliced.snapshots[i];
    CHECK(snapshot.cycle % 16 == 0);
    // the results that arrived before the snapshot's cycle, from the full run's arrivals
    uint64_t arrived = 0;
    for (uint64_t cycle : plain.arrivalCycles) arrived += cycle < snapshot.cycle;
    CHECK(snapshot.results == arrived);
    CHECK(arrived >= plan.afterResults[i]);
    CHECK(snapshot.statistics.totalCycles == snapshot.cycle);
  }
  CHECK(sliced.snapshots[0].statistics.allCores().jobs <
        sliced.snapshots[1].statistics.allCores().jobs);

  plan.stopAtLast = true;
  const RtuRun stopped = simulateRtu(image.memory(), jobs, config, plan);
  CHECK(stopped.results.empty());
  CHECK(stopped.snapshots.back().cycle == sliced.snapshots.back().cycle);
}

TEST_CASE("Sampled estimate: the 95 % interval covers the full run for 18 of 20 seeds",
          "[sampling][slow]") {
  const CachedFrame frame = cachedFrame(6, 640, 360, 8);
  const SvoImage& image = frame.image;
  const std::vector<HostRecord>& jobs = frame.jobs;
  const RtuConfig& config = frame.config;
  const double full = static_cast<double>(simulateRtu(image.memory(), jobs, config).totalCycles);
  SampleSpec spec;
  spec.fraction = 0.5;  // 35 strata of 1024 rays here; 10 % of a 1080p frame gives 40 (bench)
  int covered = 0;
  double worst = 0;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    spec.seed = seed;
    const SampledRun run = runSampled(image.memory(), jobs, config, spec);
    CHECK(run.plan.simulatedRays() <= jobs.size() / 2);
    covered += run.totalCycles.low <= full && full <= run.totalCycles.high;
    worst = std::max(worst, std::abs(run.totalCycles.estimate / full - 1));
  }
  INFO("worst relative error " << worst);
  CHECK(covered >= 18);
  CHECK(worst < 0.05);
}

}  // namespace rtu
