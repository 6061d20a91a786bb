// The SystemC RTU model (src/run/rtu_simulation.h) across its configuration space: core counts,
// scheduling policies, memory hierarchies, host back-pressure, the reorder buffer and invalid
// settings. The reference for every per-ray result is the untimed golden model; cycle counts are
// only asserted where they follow from the thesis RTL (worked out by hand in comments, using the
// hand-counted trees of test_rtl_cycle_model.cpp) or are bounds that must hold for any timing.
//
// Latency facts used below (thesis appendix C, checked against the RTL cycle model in
// test_rtl_cycle_model.cpp and test_rtu_equivalence.cpp):
//   - a job whose host handshake is in cycle a reaches the job manager output no earlier than
//     a + 6 (six pipeline stages);
//   - a core that takes a job in cycle d is in INIT in d + 1, spends its cost c (INIT .. POP,
//     blocked cycles included) until OUT in d + 1 + c, hands the result to its empty result
//     buffer in that cycle, and the host can take it from d + 2 + c on, in a cycle whose
//     result_select (cycle mod cores) names the core;
//   - host records cross one per cycle at most.
// So the result of job k can never arrive before k + 8 + c_k.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/timing_limits.h"
#include "inputs/camera.h"
#include "kind_fixture.h"
#include "kinds/svo/golden_model.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/ray_setup.h"
#include "kinds/svo/svo_builder.h"
#include "kinds/svo/traversal_core.h"
#include "run/rtu_simulation.h"
#include "sim/kernel/cycle_clock.h"
#include "sim/memory/cache_array.h"
#include "svo_descriptor.h"

namespace rtu {
namespace {

// ---------------------------------------------------------------------------------------------
// Workloads

// A kind's test scenes at depth 6 (or its fixture's detail 6), 24x16 rays each. Built once per
// process: the scenes are shared by several test cases.
template <class Kind = SvoKind>
const std::vector<typename KindFixture<Kind>::Frame>& frameScenes() {
  using Fixture = KindFixture<Kind>;
  static const std::vector<typename Fixture::Frame> scenes = [] {
    std::vector<typename Fixture::Frame> all;
    for (const std::string& name : Fixture::scenes())
      all.push_back(Fixture::frame(name, 6, 24, 16));
    return all;
  }();
  return scenes;
}

using SvoFrame = KindFixture<SvoKind>::Frame;

const SvoFrame& sceneNamed(const std::string& name) {
  for (const SvoFrame& s : frameScenes())
    if (s.scene == name) return s;
  throw std::logic_error("no scene " + name);
}

// Hand-counted trees of test_rtl_cycle_model.cpp (costs from test_traversal_costs.cpp), in one
// image; a job picks a tree by its root address.
struct ConfigurationTree {
  uint32_t root;
  uint32_t cost;  // of the centre-line job
};
constexpr ConfigurationTree kFullRoot{0, 2};   // INIT EVAL(hit)
constexpr ConfigurationTree kEmptyRoot{1, 5};  // INIT EVAL NEXT EVAL NEXT
constexpr ConfigurationTree kOnePush{2, 7};    // INIT EVAL NEXT EVAL PUSH INIT EVAL
constexpr ConfigurationTree kFiveLevels{
    7, 17};  // INIT EVAL, then PUSH INIT EVAL for each of five levels

const std::vector<uint32_t>& treeImage() {
  static const std::vector<uint32_t> image = [] {
    std::vector<uint32_t> words = {
        descriptor(false, 0, 0xFF, 0xFF),                                     // kFullRoot
        descriptor(false, 0, 0x00, 0x00),                                     // kEmptyRoot
        descriptor(false, 1, 0x80, 0x00), descriptor(false, 0, 0x01, 0x01),   // kOnePush
        descriptor(false, 1, 0x88, 0x00), descriptor(false, 0, 0x02, 0x02),   // (kPopBack)
        descriptor(false, 0, 0x01, 0x01), descriptor(false, 1, 0xFF, 0x00)};  // kFiveLevels
    for (int level = 1; level <= 5; ++level)
      for (uint32_t slot = 0; slot < 8; ++slot)
        words.push_back(level < 5 ? descriptor(false, 8 - slot, 0xFF, 0x00)
                                  : descriptor(false, 0, 0xFF, 0xFF));
    return words;
  }();
  return image;
}

// t0 = (-8, -8, 2), t1 = (8, 8, 4): the centre-line job of test_traversal_costs.cpp.
std::vector<TValueRecord> treeJobs(const std::vector<ConfigurationTree>& trees) {
  std::vector<TValueRecord> jobs;
  for (const ConfigurationTree& tree : trees) {
    TValueRecord job;
    job.id = static_cast<uint32_t>(jobs.size());
    job.t0Bits = {floatBits(-8.0f), floatBits(-8.0f), floatBits(2.0f)};
    job.t1Bits = {floatBits(8.0f), floatBits(8.0f), floatBits(4.0f)};
    job.root = tree.root;
    jobs.push_back(job);
  }
  // The premise of every hand count: the golden model agrees with the hand-worked costs.
  GoldenModel golden(WordMemory(treeImage()), GoldenConfig{});
  for (size_t i = 0; i < jobs.size(); ++i) REQUIRE(golden.trace(jobs[i]).cost == trees[i].cost);
  return jobs;
}

RtuRun runTrees(const std::vector<ConfigurationTree>& trees, const RtuConfig& config) {
  return simulateRtu(WordMemory(treeImage()), treeJobs(trees), config);
}

using Cycles = std::vector<uint64_t>;

Cycles iota(size_t n) {
  Cycles v(n);
  std::iota(v.begin(), v.end(), uint64_t{0});
  return v;
}

// ---------------------------------------------------------------------------------------------
// Configurations

MemoryConfig tinyMemory(Replacement replacement) {
  MemoryConfig memory;  // cached
  memory.l1.sizeBytes = 256;
  memory.l1.lineBytes = 32;
  memory.l1.ways = 1;  // direct-mapped
  memory.l1.replacement = replacement;
  memory.l1.seed = 11;
  memory.l2.sizeBytes = 1024;
  memory.l2.lineBytes = 64;
  memory.l2.ways = 4;
  memory.l2.replacement = replacement;
  memory.l2.maxOutstandingMisses = 2;
  memory.l2.seed = 23;
  memory.dram.latency = 200;
  memory.dram.bytesPerCycle = 1.0;
  return memory;
}

struct NamedMemory {
  std::string name;
  MemoryConfig config;
};

// Every latency zero: an L1 hit and an L2 hit cost nothing, a DRAM line one transfer cycle.
MemoryConfig zeroLatencyMemory() {
  MemoryConfig memory;
  memory.l1.hitLatency = 0;
  memory.l1.sizeBytes = 512;
  memory.l2.hitLatency = 0;
  memory.l2.sizeBytes = 2048;
  memory.dram.latency = 0;
  memory.dram.bytesPerCycle = 1024.0;
  return memory;
}

std::vector<NamedMemory> memories() {
  return {{"ideal", RtuConfig::idealMemory()},
          {"default cached", MemoryConfig{}},
          {"tiny random", tinyMemory(Replacement::Random)},
          {"tiny fifo", tinyMemory(Replacement::Fifo)},
          {"zero latency", zeroLatencyMemory()}};
}

const std::vector<SchedulerPolicy> kPolicies = {SchedulerPolicy::CyclicFirstAvailable,
                                                SchedulerPolicy::RoundRobin,
                                                SchedulerPolicy::FirstAvailable};

std::string describe(const RtuConfig& c) {
  std::ostringstream out;
  out << c.cores << " cores, " << toString(c.scheduler) << ", "
      << (c.memory.ideal ? "ideal memory"
                         : "L1 " + std::to_string(c.memory.l1.sizeBytes) + " B " +
                               toString(c.memory.l1.replacement) + ", L2 " +
                               std::to_string(c.memory.l2.sizeBytes) + " B")
      << ", input " << c.hostInput.bytesPerCycle << " B/c p=" << c.hostInput.activeProbability
      << " seed " << c.hostInput.seed << ", output " << c.hostOutput.bytesPerCycle
      << " B/c p=" << c.hostOutput.activeProbability << " seed " << c.hostOutput.seed
      << ", reorder " << c.reorderCapacity << ", " << c.coreConfig<SvoKind>().stackFrames
      << " frames";
  return out.str();
}

// Memory accesses the kind's behaviour makes for its jobs (EVAL, PUSH through a far pointer for
// SVO: one word each; the BVH's reading states: one 4-word access each), counted by running the
// behaviour itself, independently of the cache models: each is one L1 access.
template <class Kind = SvoKind, class Record>
uint64_t wordsRead(const WordMemory& memory, const std::vector<Record>& records,
                   const RtuConfig& config) {
  typename Kind::Setup setup(memory, config.jobManager, config.coreConfig<Kind>());
  typename Kind::Behaviour behaviour = Kind::behaviour(config.coreConfig<Kind>());
  uint64_t reads = 0;
  const auto read = [&](uint32_t address) { return memory.read(address); };
  for (const Record& record : records) {
    Kind::start(behaviour, setUpHostRecord<Kind>(setup, HostRecord{record}).job);
    while (behaviour.busy()) {
      reads += behaviour.readsMemory();
      behaviour.step(read);
    }
    behaviour.finish();
  }
  return reads;
}

// ---------------------------------------------------------------------------------------------
// Checks that hold for every run

bool isPermutation(const Cycles& indices, size_t n) {
  Cycles sorted = indices;
  std::sort(sorted.begin(), sorted.end());
  return sorted == iota(n);
}

// Results against the golden model: every field exact; the cost exact with ideal memory, else
// the golden cost plus the cycles the core spent BLOCKED on memory.
void checkResults(const RtuRun& run, const std::vector<CoreKindResult>& expected,
                  const RtuConfig& config) {
  REQUIRE(run.results.size() == expected.size());
  REQUIRE(run.jobIndices.size() == expected.size());
  REQUIRE(run.arrivalCycles.size() == expected.size());
  REQUIRE(isPermutation(run.jobIndices, expected.size()));
  const std::vector<CoreKindResult> ordered = resultsInJobOrder(run);
  std::vector<uint64_t> blockedOf(expected.size());
  for (size_t i = 0; i < run.results.size(); ++i)
    blockedOf[run.jobIndices[i]] = run.blockedCycles[i];
  uint64_t extra = 0, mismatches = 0, cheaper = 0;
  for (size_t k = 0; k < expected.size(); ++k) {
    // The cost is the state count, as golden's; cycles BLOCKED on memory are counted beside it.
    const CoreKindResult& got = ordered[k];
    if (resultCost(got) < resultCost(expected[k])) {
      ++cheaper;
      continue;
    }
    extra += blockedOf[k];
    if (got != expected[k]) {
      ++mismatches;
      UNSCOPED_INFO("job " << k << ": hit " << resultHit(got) << "/" << resultHit(expected[k])
                           << ", cost " << resultCost(got) << "/" << resultCost(expected[k]));
    }
  }
  CHECK(mismatches == 0);
  CHECK(cheaper == 0);

  uint64_t blocked = 0, busy = 0, jobs = 0, overflows = 0;
  for (const CoreStatistics& core : run.statistics.coreTimes) {
    blocked += core.blockedCycles;
    busy += core.busyCycles;
    jobs += core.jobs;
    overflows += core.stackOverflows;
  }
  const uint64_t goldenCost =
      std::accumulate(expected.begin(), expected.end(), uint64_t{0},
                      [](uint64_t sum, const CoreKindResult& r) { return sum + resultCost(r); });
  CoreStatistics golden;  // the kinds' counters of the golden results
  for (const CoreKindResult& r : expected) countResult(r, golden);
  const uint64_t goldenOverflows = golden.stackOverflows;
  CHECK(run.statistics.coreTimes.size() == static_cast<size_t>(config.cores));
  CHECK(extra == blocked);
  if (config.memory.ideal) CHECK(blocked == 0);
  CHECK(busy == goldenCost);  // INIT .. POP cycles, blocked ones excluded
  CHECK(jobs == expected.size());
  CHECK(overflows == goldenOverflows);
  CHECK(run.statistics.allCores().stackOverflows == goldenOverflows);
  // Each core's busy, blocked and OUT cycles fit in the run (idle is the rest).
  uint64_t overfull = 0;
  for (const CoreStatistics& core : run.statistics.coreTimes)
    if (core.busyCycles + core.blockedCycles + core.outCycles > run.totalCycles) ++overfull;
  CHECK(overfull == 0);
  if (!expected.empty()) CHECK(run.statistics.resultBuffersMaxFull >= 1);
  CHECK(run.statistics.resultBuffersMaxFull <= static_cast<uint64_t>(config.cores));
}

// Timing facts that hold for any configuration (see the top of the file; the 6 there is the
// job manager's P_STAGES).
void checkTiming(const RtuRun& run, const RtuConfig& config) {
  const size_t n = run.results.size();
  uint64_t notIncreasing = 0, tooEarly = 0;
  for (size_t i = 1; i < n; ++i)
    if (run.arrivalCycles[i] <= run.arrivalCycles[i - 1]) ++notIncreasing;
  for (size_t i = 0; i < n; ++i)
    if (run.arrivalCycles[i] < run.jobIndices[i] + static_cast<uint64_t>(config.jobManager.stages) +
                                   2 + resultCost(run.results[i]) + run.blockedCycles[i])
      ++tooEarly;
  CHECK(notIncreasing == 0);
  CHECK(tooEarly == 0);
  CHECK(run.totalCycles == (n == 0 ? 0 : run.arrivalCycles.back() + 1));
  CHECK(run.statistics.totalCycles == run.totalCycles);
  CHECK(run.statistics.rays == n);
  CHECK(run.statistics.cores == config.cores);
  CHECK(run.statistics.scheduler == toString(config.scheduler));
  CHECK(run.statistics.idealMemory == config.memory.ideal);
}

// The scheduler's wait statistics: eq. 6.7 for cfa (a ready core is reached within cores - 1
// cycles, since an idle core stays ready until the scheduler gives it a job), no wait at all for
// fa when a core is ready, one histogram entry per job, and round-robin's strict rotation seen
// in the number of jobs each core ran and in the cores the results come from.
void checkScheduler(const RtuRun& run, const RtuConfig& config) {
  const RtuStatistics& s = run.statistics;
  const uint64_t cores = static_cast<uint64_t>(config.cores);
  uint64_t histogramJobs = 0, histogramMax = 0;
  for (const auto& [wait, jobs] : s.waitHistogram) {
    histogramJobs += jobs;
    if (jobs > 0) histogramMax = std::max(histogramMax, wait);
  }
  CHECK(histogramJobs == run.results.size());
  // A job's wait is the time it stalls the job manager's output: the waits add up to the
  // job manager's stall cycles.
  uint64_t waited = 0;
  for (const auto& [wait, jobs] : s.waitHistogram) waited += wait * jobs;
  CHECK(waited == s.jobManagerStallCycles);
  CHECK(histogramMax == s.maxWait);
  CHECK(s.maxWaitWithReadyCore <= s.maxWait);
  switch (config.scheduler) {
    case SchedulerPolicy::CyclicFirstAvailable:
      CHECK(s.maxWaitWithReadyCore <= cores - 1);
      CHECK(s.waitBound() == static_cast<int64_t>(cores - 1));
      break;
    case SchedulerPolicy::FirstAvailable:
      CHECK(s.maxWaitWithReadyCore == 0);
      CHECK(s.waitBound() == 0);
      break;
    case SchedulerPolicy::RoundRobin: {
      // Job k goes to core k mod cores: core i runs the jobs i, i + cores, ...
      const uint64_t jobs = run.results.size();
      for (uint64_t i = 0; i < cores; ++i) {
        INFO("core " << i);
        CHECK(s.coreTimes[i].jobs == (jobs > i ? (jobs - i + cores - 1) / cores : 0));
      }
      // Without a reorder buffer the host takes core i's result only in cycles with
      // result_select = i (cycle mod cores), so a result's arrival cycle names its core: the
      // core of every job is visible, and it must be job mod cores.
      if (config.reorderCapacity == 0) {
        uint64_t outOfTurn = 0;
        for (size_t i = 0; i < run.results.size(); ++i)
          if (run.arrivalCycles[i] % cores != run.jobIndices[i] % cores) ++outOfTurn;
        CHECK(outOfTurn == 0);
      }
      CHECK(s.waitBound() == -1);
      break;
    }
  }
}

// Cache statistics against the traversal's own count of memory reads: every read is one L1
// access, every L1 miss one L2 request, every L2 miss one DRAM line.
void checkMemory(const RtuRun& run, const RtuConfig& config, uint64_t reads) {
  const RtuStatistics& s = run.statistics;
  if (config.memory.ideal) {
    CHECK(s.l1.empty());
    return;
  }
  REQUIRE(s.l1.size() == static_cast<size_t>(config.cores));
  uint64_t accesses = 0, misses = 0;
  for (const CacheStats& l1 : s.l1) {
    CHECK(l1.accesses == l1.hits + l1.merged + l1.misses);
    accesses += l1.accesses;
    misses += l1.misses;
  }
  CHECK(accesses == reads);
  CHECK(s.l2.cache.accesses == misses);
  CHECK(s.l2.cache.accesses == s.l2.cache.hits + s.l2.cache.merged + s.l2.cache.misses);
  CHECK(s.l2.dram.reads == s.l2.cache.misses);
  CHECK(s.l2.dram.bytes == s.l2.cache.misses * config.memory.l2.lineBytes);
  // An L1 hit still costs its hit latency, so every read blocks the core for at least that.
  uint64_t blocked = 0;
  for (const CoreStatistics& core : s.coreTimes) blocked += core.blockedCycles;
  CHECK(blocked >= reads * config.memory.l1.hitLatency);
  // A line from DRAM takes at least one transfer cycle, for which its reader is blocked.
  CHECK(blocked >= s.l2.cache.misses);
}

void checkRun(const RtuRun& run, const std::vector<CoreKindResult>& expected,
              const RtuConfig& config, uint64_t reads) {
  checkResults(run, expected, config);
  checkTiming(run, config);
  checkScheduler(run, config);
  checkMemory(run, config, reads);
}

Cycles arrivalByJob(const RtuRun& run) {
  Cycles arrival(run.results.size());
  for (size_t i = 0; i < run.results.size(); ++i) arrival[run.jobIndices[i]] = run.arrivalCycles[i];
  return arrival;
}

uint64_t sumOfCostsPlusTwo(const RtuRun& run) {
  uint64_t sum = 0;
  for (size_t i = 0; i < run.results.size(); ++i)
    sum += resultCost(run.results[i]) + run.blockedCycles[i] + 2;
  return sum;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// 1. Results across scenes, core counts, schedulers and memories

TEMPLATE_LIST_TEST_CASE("Every configuration returns the golden model's results", "[rtu]",
                        TestedKinds) {
  for (const auto& scene : frameScenes<TestType>()) {
    const RtuConfig base = kindConfig<TestType>();
    const std::vector<CoreKindResult> expected =
        KindFixture<TestType>::golden(scene.memory(), base, scene.jobs);
    const uint64_t reads = wordsRead<TestType>(scene.memory(), scene.jobs, base);
    for (const NamedMemory& memory : memories()) {
      for (int cores : {1, 2, 4, 16}) {
        for (SchedulerPolicy policy : kPolicies) {
          RtuConfig config = base;
          config.cores = cores;
          config.scheduler = policy;
          config.memory = memory.config;
          INFO(scene.scene << " (" << scene.jobs.size() << " rays), " << memory.name << ": "
                           << describe(config));
          const RtuRun run = simulateRtu(scene.memory(), scene.jobs, config);
          checkRun(run, expected, config, reads);
          if (cores == 1) {
            // One core: the job manager always has the next job waiting, so each job holds
            // the core for its handshake, its cost and OUT, back to back from the first job's
            // dispatch (cycle 6 for a t-value record), and the last result leaves in the cycle
            // after its OUT.
            CHECK(run.totalCycles == KindFixture<TestType>::firstDispatch(base.jobManager) +
                                         sumOfCostsPlusTwo(run) + 1);
            CHECK(run.jobIndices == iota(scene.jobs.size()));
          }
        }
      }
    }
  }
}

TEMPLATE_LIST_TEST_CASE("Shared triangle units return the golden model's results", "[rtu]",
                        TestedKinds) {
  // core.triangle.shared_by 1, 2 and 4 over every memory and policy: a test's wait for its unit
  // is timing only, and with a unit a core no test waits.
  if constexpr (HasTriangleUnit<TestType>::value) {
    const auto& scene = frameScenes<TestType>().front();
    const RtuConfig base = kindConfig<TestType>();
    const std::vector<CoreKindResult> expected =
        KindFixture<TestType>::golden(scene.memory(), base, scene.jobs);
    const uint64_t reads = wordsRead<TestType>(scene.memory(), scene.jobs, base);
    for (const NamedMemory& memory : memories()) {
      for (int cores : {4, 16}) {
        for (int sharedBy : {1, 2, 4}) {
          for (SchedulerPolicy policy : kPolicies) {
            RtuConfig config = base;
            config.cores = cores;
            config.scheduler = policy;
            config.memory = memory.config;
            config.triangleSharedBy = sharedBy;
            INFO(scene.scene << ", " << memory.name << ": " << describe(config) << ", shared by "
                             << sharedBy);
            const RtuRun run = simulateRtu(scene.memory(), scene.jobs, config);
            checkRun(run, expected, config, reads);
            if (sharedBy == 1) CHECK(run.statistics.allCores().unitStallCycles == 0);
          }
        }
      }
    }
  }
}

TEMPLATE_LIST_TEST_CASE("Other arithmetic, stack depths and job manager depths", "[rtu]",
                        TestedKinds) {
  // The golden model with the same configuration is the reference.
  using Fixture = KindFixture<TestType>;
  for (const auto& scene : frameScenes<TestType>()) {
    for (int stages : {1, 3, 12}) {
      for (bool other : {false, true}) {
        RtuConfig config = kindConfig<TestType>();
        config.cores = stages == 3 ? 1 : 4;
        config.scheduler = stages == 12 ? SchedulerPolicy::FirstAvailable
                                        : SchedulerPolicy::CyclicFirstAvailable;
        config.jobManager.stages = stages;
        if (other) {
          Fixture::otherArithmetic(config);
          config.memory = MemoryConfig{};
        }
        INFO(scene.scene << ", " << stages << " job manager stages, "
                         << config.coreConfig<SvoKind>().format.describe() << ": "
                         << describe(config));
        const std::vector<CoreKindResult> expected =
            Fixture::golden(scene.memory(), config, scene.jobs);
        const RtuRun run = simulateRtu(scene.memory(), scene.jobs, config);
        checkRun(run, expected, config, wordsRead<TestType>(scene.memory(), scene.jobs, config));
        // (checkTiming: job k's result arrives no earlier than k + stages + 2 + cost.)
        // One core: dispatches back to back from the first job's (cycle `stages`, P_STAGES, for
        // a t-value record), as with 6 stages.
        if (config.cores == 1)
          CHECK(run.totalCycles ==
                Fixture::firstDispatch(config.jobManager) + sumOfCostsPlusTwo(run) + 1);
      }
    }
  }
}

TEST_CASE("The clock changes the time unit only", "[rtu]") {
  const SvoFrame& scene = sceneNamed("terrain");
  RtuConfig config;
  config.cores = 4;
  config.memory = MemoryConfig{};
  const RtuRun reference = simulateRtu(scene.memory(), scene.jobs, config);
  for (double mhz : {1.0, 333.0, 1e6}) {
    config.clockMhz = mhz;
    INFO(mhz << " MHz");
    const RtuRun run = simulateRtu(scene.memory(), scene.jobs, config);
    CHECK(run.arrivalCycles == reference.arrivalCycles);
    CHECK(run.results == reference.results);
    CHECK(run.statistics.clockMhz == mhz);
    // Rays per second at the simulated clock: rays / (cycles / f).
    CHECK(run.statistics.raysPerSecond() == Approx(static_cast<double>(scene.jobs.size()) * mhz *
                                                   1e6 / static_cast<double>(run.totalCycles)));
  }
}

// ---------------------------------------------------------------------------------------------
// 2. Scheduler

TEST_CASE("Scheduler waits on a hand-counted job pair", "[rtu]") {
  // Two cores; jobs of cost 17 (five levels) and 2 (full root); the input link moves a record
  // every 2 cycles (16 bytes per cycle: nextAllowed(c) = ceil(c + 2)).
  // Job 0: host handshake 0, job manager output 6, select 6 mod 2 = 0, core 0 ready: dispatched
  // in 6 under every policy (wait 0). Core 0 is busy until IDLE in 6 + 2 + 17 = 25.
  // Job 1: host handshake 2 (the job manager output is empty, so it accepts), output in 8.
  //   cfa: select 8 mod 2 = 0 names the busy core 0 although core 1 is ready: dispatched to core
  //        1 in 9, wait 1 = cores - 1, the eq. 6.7 worst case.
  //   rr, fa: core 1 (next in line / lowest ready) in 8, wait 0.
  // Results: job 1 (core 1, cost 2) is in its result buffer from d + 4 = 13 (cfa) or 12 (rr,
  // fa) and leaves in the first cycle with result_select = 1: 13 either way. Job 0 is there from
  // 25 and leaves in the first cycle with select 0: 26. Total 27.
  const std::vector<ConfigurationTree> trees = {kFiveLevels, kFullRoot};
  for (SchedulerPolicy policy : kPolicies) {
    RtuConfig config;
    config.cores = 2;
    config.scheduler = policy;
    config.hostInput.bytesPerCycle = 16.0;
    INFO(describe(config));
    const RtuRun run = runTrees(trees, config);
    CHECK(run.jobIndices == Cycles{1, 0});
    CHECK(run.arrivalCycles == Cycles{13, 26});
    CHECK(run.totalCycles == 27);
    const uint64_t wait = policy == SchedulerPolicy::CyclicFirstAvailable ? 1 : 0;
    CHECK(run.statistics.maxWait == wait);
    CHECK(run.statistics.maxWaitWithReadyCore == wait);
    const std::map<uint64_t, uint64_t> histogram =
        wait == 0 ? std::map<uint64_t, uint64_t>{{0, 2}}
                  : std::map<uint64_t, uint64_t>{{0, 1}, {1, 1}};
    CHECK(run.statistics.waitHistogram == histogram);
    CHECK(run.statistics.coreTimes[0].jobs == 1);
    CHECK(run.statistics.coreTimes[1].jobs == 1);
  }
}

TEST_CASE("A job that waits for a busy core is not a case of eq. 6.7", "[rtu]") {
  // test_rtl_cycle_model.cpp, "Two cores take jobs in turn", cost 5: jobs 0 and 1 are
  // dispatched in 6 and 7 (wait 0); job 2 reaches the job manager output in 8, when both cores
  // are busy, and goes to core 0 in 14: wait 6, but no core was ready when it became pending.
  RtuConfig config;
  config.cores = 2;
  const RtuRun run = runTrees({kEmptyRoot, kEmptyRoot, kEmptyRoot}, config);
  CHECK(run.arrivalCycles == Cycles{14, 15, 22});
  CHECK(run.statistics.maxWait == 6);
  CHECK(run.statistics.maxWaitWithReadyCore == 0);
  CHECK(run.statistics.waitHistogram == std::map<uint64_t, uint64_t>{{0, 2}, {6, 1}});
}

// ---------------------------------------------------------------------------------------------
// 3. Host back-pressure

TEST_CASE("Random and paced host links lose, duplicate and reorder nothing", "[rtu]") {
  // Pacing of a link at R bytes per cycle (src/rtu/host_link.cpp, docs/cycle-semantics.md):
  // after a record crosses in cycle c,
  //   e = max(e, c) + 32 / R,   the next record may cross from max(c + 1, ceil(e)) on.
  // Whatever the rounding, e grows by 32 / R per record and a record never crosses before its
  // e, so records i < j cross in cycles c_i, c_j with
  //   c_j >= e_j >= e_(i+1) + (j - i - 1) 32 / R > (c_i - 1) + (j - i) 32 / R,
  // i.e. no stretch of records moves faster than R: 3 (c_j - c_i) > 32 (j - i) - 3 at R = 3,
  // and consecutive records are at least ceil(32 / 3) - 1 = 10 cycles apart.
  // (As written, host_link.cpp takes max(e, c) with c >= ceil(e) >= e at every crossing, so the
  // fraction is dropped and every gap is at least 11; docs/cycle-semantics.md says the fraction
  // carries over, which would allow gaps of 10. The bound above holds either way; the
  // documented long-run rate is checked by "A saturated link moves R bytes per cycle".)
  // The input link is the same code: job k crosses no earlier than ceil(32 k / 3), and its
  // result arrives no earlier than that + 8 + cost.
  const auto fasterThanThreeBytes = [](const Cycles& crossings) {
    uint64_t violations = 0;
    for (size_t i = 0; i < crossings.size(); ++i)
      for (size_t j = i + 1; j < crossings.size(); ++j)
        if (3 * (crossings[j] - crossings[i]) + 3 <= 32 * (j - i)) ++violations;
    return violations;
  };

  struct Link {
    double bytesPerCycle, probability;
  };
  const std::vector<std::pair<Link, Link>> links = {
      {{0.0, 0.3}, {0.0, 0.7}}, {{0.0, 0.7}, {0.0, 0.3}}, {{0.0, 0.5}, {0.0, 0.5}},
      {{3.0, 1.0}, {0.0, 1.0}}, {{0.0, 1.0}, {3.0, 1.0}}, {{3.0, 1.0}, {3.0, 1.0}},
      {{3.0, 0.5}, {3.0, 0.6}}};

  uint64_t seed = 1;
  for (const char* name : {"sphere", "noise"}) {
    const SvoFrame& scene = sceneNamed(name);
    const std::vector<CoreKindResult> expected =
        KindFixture<SvoKind>::golden(scene.memory(), RtuConfig{}, scene.jobs);
    const uint64_t reads = wordsRead(scene.memory(), scene.jobs, RtuConfig{});
    for (const NamedMemory& memory : {memories()[0], memories()[1]}) {
      for (int cores : {1, 4, 16}) {
        for (SchedulerPolicy policy : kPolicies) {
          RtuConfig free;
          free.cores = cores;
          free.scheduler = policy;
          free.memory = memory.config;
          const RtuRun unthrottled = simulateRtu(scene.memory(), scene.jobs, free);
          for (const auto& [in, out] : links) {
            RtuConfig config = free;
            config.hostInput = HostLinkConfig{in.bytesPerCycle, in.probability, ++seed};
            config.hostOutput = HostLinkConfig{out.bytesPerCycle, out.probability, ++seed * 7};
            INFO(name << ", " << memory.name << ": " << describe(config));
            const RtuRun run = simulateRtu(scene.memory(), scene.jobs, config);
            checkRun(run, expected, config, reads);
            if (out.bytesPerCycle > 0) {
              CHECK(fasterThanThreeBytes(run.arrivalCycles) == 0);
              uint64_t close = 0;
              for (size_t i = 1; i < run.arrivalCycles.size(); ++i)
                if (run.arrivalCycles[i] - run.arrivalCycles[i - 1] < 10) ++close;
              CHECK(close == 0);
            }
            if (in.bytesPerCycle > 0) {
              uint64_t early = 0;
              for (size_t i = 0; i < run.results.size(); ++i) {
                const uint64_t k = run.jobIndices[i];
                const uint64_t crossing = (32 * k + 2) / 3;  // ceil(32 k / 3)
                if (run.arrivalCycles[i] <
                    crossing + 8 + resultCost(run.results[i]) + run.blockedCycles[i])
                  ++early;
              }
              CHECK(early == 0);
            }
            // Holding the host off can only delay results when the core that runs each job
            // does not depend on timing and the memory has no shared state: one core (any
            // policy, any memory: a single chain of max-plus delays) or round-robin on ideal
            // memory (job k always on core k mod cores, each step a max or a "next cycle with
            // select = i" of earlier steps). cfa (cycle-numbered select) and fa (whichever core
            // is ready) can assign jobs differently, and shared caches interleave differently,
            // so no ordering is claimed for them.
            if (cores == 1 || (policy == SchedulerPolicy::RoundRobin && config.memory.ideal)) {
              const Cycles late = arrivalByJob(run), early = arrivalByJob(unthrottled);
              uint64_t earlier = 0;
              for (size_t k = 0; k < late.size(); ++k)
                if (late[k] < early[k]) ++earlier;
              CHECK(earlier == 0);
              CHECK(run.totalCycles >= unthrottled.totalCycles);
            }
            if (cores == 1) CHECK(run.jobIndices == iota(scene.jobs.size()));
            // One core, random output activity: a result offered in a cycle where the sink is
            // inactive arrives later than unthrottled (where it is taken when first offered,
            // and it is offered no earlier when throttled). All 384 results meet an active sink
            // with chance at most 0.7^384, so the seeded run must differ.
            if (cores == 1 && out.probability < 1.0)
              CHECK(run.arrivalCycles != unthrottled.arrivalCycles);
          }
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// 4. Reorder buffer

TEST_CASE("The reorder buffer delivers results in job order", "[rtu]") {
  for (const char* name : {"sphere", "terrain", "noise"}) {
    const SvoFrame& scene = sceneNamed(name);
    const std::vector<CoreKindResult> expected =
        KindFixture<SvoKind>::golden(scene.memory(), RtuConfig{}, scene.jobs);
    const uint64_t reads = wordsRead(scene.memory(), scene.jobs, RtuConfig{});
    for (int capacity : {1, 4, 64}) {
      for (int cores : {1, 4, 16}) {
        for (SchedulerPolicy policy : kPolicies) {
          for (bool cached : {false, true}) {
            RtuConfig config;
            config.cores = cores;
            config.scheduler = policy;
            config.reorderCapacity = capacity;
            if (cached) config.memory = MemoryConfig{};
            if (policy == SchedulerPolicy::RoundRobin) {
              // and under host back-pressure
              config.hostOutput = HostLinkConfig{0.0, 0.5, 99};
              config.hostInput = HostLinkConfig{0.0, 0.6, 98};
            }
            INFO(name << ": " << describe(config));
            RtuRun run;
            REQUIRE_NOTHROW(run = simulateRtu(scene.memory(), scene.jobs, config));
            CHECK(run.jobIndices == iota(scene.jobs.size()));
            if (!cached) CHECK(run.results == expected);  // cached: checkRun, costs differ
            checkRun(run, expected, config, reads);
            CHECK(run.statistics.reorderMaxOccupancy >= 1);
            CHECK(run.statistics.reorderMaxOccupancy <= static_cast<uint64_t>(capacity));
          }
        }
      }
    }
  }
}

TEST_CASE("A one-entry reorder buffer on a hand-counted pair", "[rtu]") {
  // Two cores, jobs of cost 17 and 2, unlimited host: job 0 to core 0 in 6, job 1 to core 1 in 7.
  // Without the buffer job 1 leaves first (in its result buffer from 7 + 4 = 11, select 1 in 11)
  // and job 0 in 26 (buffered from 25, select 0 in 26).
  // With a one-entry buffer job 1 is outside the window (sequence 1 >= nextDue 0 + 1): the
  // reorder buffer refuses it whenever result_select offers it, and it waits in its result
  // buffer. Job 0 is offered in 26 (26 mod 2 = 0) and enters the reorder buffer, which offers it
  // to the host in 27, taken in 27. In 27 result_select offers job 1 again, but nextDue is still
  // 0 (it advances with the host handshake at the end of 27): refused. In 28 the select names
  // core 0, empty. In 29 job 1 is offered and inside the window: taken, offered to the host in 30
  // and taken in 30. Total 31.
  RtuConfig config;
  config.cores = 2;
  const RtuRun plain = runTrees({kFiveLevels, kFullRoot}, config);
  CHECK(plain.jobIndices == Cycles{1, 0});
  CHECK(plain.arrivalCycles == Cycles{11, 26});

  config.reorderCapacity = 1;
  const RtuRun ordered = runTrees({kFiveLevels, kFullRoot}, config);
  CHECK(ordered.jobIndices == Cycles{0, 1});
  CHECK(ordered.arrivalCycles == Cycles{27, 30});
  CHECK(ordered.totalCycles == 31);
  CHECK(ordered.statistics.reorderMaxOccupancy == 1);
}

// ---------------------------------------------------------------------------------------------
// 5. Exact host pacing, by hand

TEST_CASE("Host link pacing on one core, counted by hand", "[rtu]") {
  // One core, jobs of cost 2, 7 and 5. Unlimited links (test_rtl_cycle_model.cpp, "Jobs queue
  // behind the one busy core"): dispatched in 6, 10, 19; results in 10, 19, 26.
  // With one core and an empty result buffer, a job dispatched in d is taken by a ready host in
  // d + 2 + c; the core is IDLE (and can take the next job) in d + 2 + c as well.
  const std::vector<ConfigurationTree> trees = {kFullRoot, kOnePush, kEmptyRoot};
  RtuConfig config;
  config.cores = 1;

  SECTION("unlimited") {
    const RtuRun run = runTrees(trees, config);
    CHECK(run.arrivalCycles == Cycles{10, 19, 26});
    CHECK(run.totalCycles == 27);
  }
  SECTION("32 bytes per cycle on both links is unlimited") {
    // nextAllowed(c) = max(c + 1, ceil(max(earliest, c) + 32 / 32)) = c + 1: a record may cross
    // in every cycle, as with an unlimited link.
    config.hostInput.bytesPerCycle = 32.0;
    config.hostOutput.bytesPerCycle = 32.0;
    const RtuRun run = runTrees(trees, config);
    CHECK(run.arrivalCycles == Cycles{10, 19, 26});
    CHECK(run.totalCycles == 27);
  }
  SECTION("input at 3 bytes per cycle") {
    // Records cross in 0, ceil(32 / 3) = 11 and 22 (= ceil(11 + 32 / 3), and also
    // ceil(2 x 32 / 3) = 22, so whether or not the fraction carries over; see the
    // back-pressure test).
    // Job 0: output 6, dispatched 6, taken 6 + 2 + 2 = 10. Job 1: output 17, the core is idle
    // since 10: dispatched 17, taken 17 + 2 + 7 = 26. Job 2: output 28, core idle since 26:
    // dispatched 28, taken 28 + 2 + 5 = 35. Total 36.
    config.hostInput.bytesPerCycle = 3.0;
    const RtuRun run = runTrees(trees, config);
    CHECK(run.arrivalCycles == Cycles{10, 26, 35});
    CHECK(run.totalCycles == 36);
  }
  SECTION("output at 3 bytes per cycle") {
    // Job 0 taken in 10; the host is ready again from 21. Job 1 is dispatched in 10 (the core is
    // IDLE in 10), OUT in 18, handed to the empty result buffer in 18, offered from 19, taken in
    // 21. Job 2 is dispatched in 19 (core IDLE after the hand-over), OUT in 25; the buffer is
    // empty from 22, so it is handed over in 25, offered from 26 and taken when the host is
    // ready again in 32 (ceil(21 + 32 / 3) = ceil(10 + 2 x 32 / 3) = 32). Total 33.
    config.hostOutput.bytesPerCycle = 3.0;
    const RtuRun run = runTrees(trees, config);
    CHECK(run.arrivalCycles == Cycles{10, 21, 32});
    CHECK(run.totalCycles == 33);
  }
  SECTION("both links at 3 bytes per cycle") {
    // Job 0 taken in 10. Job 1 dispatched in 17 (input), offered from 26 (> 21): taken in 26.
    // Job 2 dispatched in 28, OUT in 34, offered from 35, the host ready from
    // ceil(26 + 32 / 3) = 37 (26 is later than the 20.67 a carried fraction would give):
    // taken in 37. Total 38.
    config.hostInput.bytesPerCycle = 3.0;
    config.hostOutput.bytesPerCycle = 3.0;
    const RtuRun run = runTrees(trees, config);
    CHECK(run.arrivalCycles == Cycles{10, 26, 37});
    CHECK(run.totalCycles == 38);
  }
}

TEST_CASE("A saturated link moves R bytes per cycle", "[rtu]") {
  // docs/cycle-semantics.md, "Host": a record that crosses as early as allowed keeps the fraction
  // of its slot, so a saturated link moves exactly R bytes per cycle in the long run.
  //
  // The workload: 31 jobs of cost 2 on one core. Unlimited, job k is taken in 10 + 4 k
  // (test_rtl_cycle_model.cpp); the first result crosses unpaced in 10. The core produces a
  // result every 4 cycles, faster than a 32-byte record every 10.67 cycles, so from then on a
  // result is always waiting and the output link is saturated. Moving exactly 3 bytes per
  // cycle, results 1..30 need 30 x 32 / 3 = 320 cycles: the last crosses in 10 + 320 = 330, and
  // no gap is shorter than 10 (the rate is never exceeded).
  const size_t n = 31;
  RtuConfig config;
  config.cores = 1;
  const RtuRun unlimited = runTrees(std::vector<ConfigurationTree>(n, kFullRoot), config);
  Cycles fast;
  for (uint64_t k = 0; k < n; ++k) fast.push_back(10 + 4 * k);
  REQUIRE(unlimited.arrivalCycles == fast);

  for (bool output : {true, false}) {
    RtuConfig paced = config;
    (output ? paced.hostOutput : paced.hostInput).bytesPerCycle = 3.0;
    INFO(describe(paced));
    const RtuRun run = runTrees(std::vector<ConfigurationTree>(n, kFullRoot), paced);
    REQUIRE(run.arrivalCycles.size() == n);
    for (size_t i = 1; i < run.arrivalCycles.size(); ++i)
      CHECK(run.arrivalCycles[i] - run.arrivalCycles[i - 1] >= 10);
    // Input paced instead: job k enters when the link allows, and its result leaves a fixed
    // 10 cycles later (6 + 2 + cost 2, the core being idle), so the spans are the same.
    CHECK(run.arrivalCycles.back() == 10 + 320);
  }
}

TEST_CASE("32 bytes per cycle and full activity are an unlimited link, cycle for cycle", "[rtu]") {
  // nextAllowed(c) = c + 1 at 32 bytes per cycle (see above), and activeProbability = 1 draws
  // nothing, so both runs must agree in every arrival, on any configuration.
  const SvoFrame& scene = sceneNamed("terrain");
  for (int cores : {1, 4, 16}) {
    for (SchedulerPolicy policy : kPolicies) {
      RtuConfig config;
      config.cores = cores;
      config.scheduler = policy;
      const RtuRun unlimited = simulateRtu(scene.memory(), scene.jobs, config);
      config.hostInput = HostLinkConfig{32.0, 1.0, 5};
      config.hostOutput = HostLinkConfig{64.0, 1.0, 6};
      INFO(describe(config));
      const RtuRun paced = simulateRtu(scene.memory(), scene.jobs, config);
      CHECK(paced.arrivalCycles == unlimited.arrivalCycles);
      CHECK(paced.jobIndices == unlimited.jobIndices);
      CHECK(paced.results == unlimited.results);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// 7. Invalid configurations and stack overflow

TEST_CASE("Impossible RTU configurations are rejected", "[rtu]") {
  const std::vector<TValueRecord> jobs = treeJobs({kFullRoot});
  const WordMemory memory(treeImage());
  const auto rejects = [&](const RtuConfig& config) {
    INFO(describe(config));
    CHECK_THROWS_AS(simulateRtu(memory, jobs, config), std::invalid_argument);
  };
  RtuConfig config;
  for (int cores : {0, -1, kMaxCores + 1}) {
    config = RtuConfig{};
    config.cores = cores;
    rejects(config);
  }
  config = RtuConfig{};
  config.memory = MemoryConfig{};
  config.memory.l1.sizeBytes = 16;  // less than one 32-byte line
  rejects(config);
  config = RtuConfig{};
  config.memory = MemoryConfig{};
  config.memory.l2.sizeBytes = 32;  // less than one 64-byte line
  rejects(config);
  config = RtuConfig{};
  config.memory = MemoryConfig{};
  config.memory.l2.lineBytes = 16;  // shorter than the L1 line
  rejects(config);
  for (int frames : {0, -1, kMaxStackFrames + 1}) {
    config = RtuConfig{};
    config.coreConfig<SvoKind>().stackFrames = frames;
    rejects(config);
  }
  // Below 1 MHz 2^64 ps would not hold kMaxCycles; 1e-12 MHz overflowed picosecond time.
  for (double mhz : {0.0, -100.0, std::nan(""), 0.5, 1e-12, 2e6}) {
    config = RtuConfig{};
    config.clockMhz = mhz;
    rejects(config);
  }
  config = RtuConfig{};
  config.reorderCapacity = -1;
  rejects(config);
  config = RtuConfig{};
  config.hostInput.activeProbability = 0.0;
  rejects(config);
  config = RtuConfig{};
  config.hostOutput.bytesPerCycle = -3.0;
  rejects(config);
  // 1e-300 behaved as unlimited (the slot length overflowed uint64).
  for (double rate : {1e-300, 1e-4, 2e6, HUGE_VAL}) {
    config = RtuConfig{};
    config.hostInput.bytesPerCycle = rate;
    rejects(config);
  }

  // The limits themselves are fine.
  config = RtuConfig{};
  config.cores = kMaxCores;
  CHECK_NOTHROW(simulateRtu(memory, jobs, config));
  config = RtuConfig{};
  config.cores = 1;
  config.coreConfig<SvoKind>().stackFrames = 1;
  config.reorderCapacity = 1;
  config.memory = MemoryConfig{};
  config.memory.l1.sizeBytes = config.memory.l1.lineBytes * config.memory.l1.ways;
  CHECK_NOTHROW(simulateRtu(memory, jobs, config));
}

TEST_CASE("The cycle clock stops at kMaxCycles instead of wrapping picosecond time", "[rtu]") {
  const CycleClock slowest = CycleClock::atMegahertz(kMinClockMhz);
  CHECK(slowest.period().value() == 1000000);
  CHECK(slowest.until(kMaxCycles).value() <= UINT64_MAX);  // reached without throwing
  CHECK_THROWS_AS(slowest.until(kMaxCycles + 1), std::overflow_error);
  CHECK(CycleClock::atMegahertz(kMaxClockMhz).period().value() == 1);
}

TEST_CASE("Cache tag arrays that would not fit in memory are refused before the run", "[rtu]") {
  CacheConfig oneLine;
  oneLine.sizeBytes = oneLine.lineBytes = 4;
  oneLine.ways = 1;
  CacheConfig huge = oneLine;
  huge.sizeBytes = 1u << 30;  // 2^28 lines of 4 bytes
  CHECK(CacheArray::tagBytes(huge) == (uint64_t{1} << 28) * CacheArray::tagBytes(oneLine));

  RtuConfig config;
  config.memory = MemoryConfig{};
  config.memory.l1 = huge;
  config.memory.l2.lineBytes = 4;
  config.cores = kMaxCores;  // terabytes of tags
  CHECK_THROWS_WITH(validate(config), Catch::Contains("the cache tag arrays would need") &&
                                          Catch::Contains("--l1-size"));
  config.memory.ideal = true;  // no caches are made
  CHECK_NOTHROW(validate(config));
  // The case fits a 24 GiB machine but passes the 4 GiB cap: 256 MiB L1s of 4-byte lines.
  config = RtuConfig{};
  config.memory = MemoryConfig{};
  config.memory.l1.sizeBytes = 256u << 20;
  config.memory.l1.lineBytes = 4;
  config.cores = 4;
  CHECK_THROWS_WITH(validate(config), Catch::Contains("at most 4 GiB"));
}

TEST_CASE("An impossible cache is an error even with ideal memory", "[rtu]") {
  // MemoryConfig::ideal leaves the cache and DRAM settings unused, but an impossible one is
  // still an error (src/sim/memory/memory_config.h).
  RtuConfig config;
  config.memory.l1.sizeBytes = 16;  // config.memory.ideal stays true
  REQUIRE(config.memory.ideal);
  CHECK_THROWS_AS(validate(config.memory), std::invalid_argument);  // the memory's own check
  CHECK_THROWS_AS(simulateRtu(WordMemory(treeImage()), treeJobs({kFullRoot}), config),
                  std::invalid_argument);
}

TEST_CASE("No jobs: no results and no cycles", "[rtu]") {
  RtuConfig config;
  const RtuRun run = simulateRtu(WordMemory(treeImage()), std::vector<TValueRecord>{}, config);
  CHECK(run.results.empty());
  CHECK(run.totalCycles == 0);
  CHECK(run.statistics.rays == 0);
}

TEST_CASE("A two-frame stack overflows on a deep scene", "[rtu]") {
  // Depth-6 noise needs more than two frames (checked on the golden model below); with two,
  // rays that need a third report an overflow and no hit, exactly as the golden model with the
  // same stack.
  const SvoFrame& scene = sceneNamed("noise");
  for (bool cached : {false, true}) {
    for (int cores : {1, 16}) {
      RtuConfig config;
      config.cores = cores;
      config.coreConfig<SvoKind>().stackFrames = 2;
      if (cached) config.memory = MemoryConfig{};
      INFO(describe(config));
      const std::vector<CoreKindResult> expected =
          KindFixture<SvoKind>::golden(scene.memory(), config, scene.jobs);
      const std::vector<TraversalResult> svoExpected = svoResults(expected);
      const uint64_t overflows = static_cast<uint64_t>(
          std::count_if(svoExpected.begin(), svoExpected.end(),
                        [](const TraversalResult& r) { return r.stackOverflow; }));
      REQUIRE(overflows > 0);
      const RtuRun run = simulateRtu(scene.memory(), scene.jobs, config);
      checkRun(run, expected, config, wordsRead(scene.memory(), scene.jobs, config));
      uint64_t flagged = 0;
      for (const TraversalResult& r : svoResults(run.results)) {
        if (!r.stackOverflow) continue;
        ++flagged;
        CHECK_FALSE(r.hit);
      }
      CHECK(flagged == overflows);
      CHECK(run.statistics.allCores().stackOverflows == overflows);
    }
  }
  // With the RTL's eleven frames nothing overflows on this scene.
  RtuConfig thesis;
  CHECK(simulateRtu(scene.memory(), scene.jobs, thesis).statistics.allCores().stackOverflows == 0);
}

}  // namespace rtu
