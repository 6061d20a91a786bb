// The per-cycle model of the RTL top level (appendices C.1 to C.5). Expected cycle counts are
// worked out by hand from the listings, using jobs whose traversal costs were worked out by hand
// in test_traversal_costs.cpp:
//   - the host handshake of job i in cycle a puts it in valid_delay[5] (job manager out_valid) in
//     cycle a + 6 if the pipeline never stalls;
//   - core_select and result_select are both the cycle number modulo the core count;
//   - a core that takes a job in cycle d (its IDLE handshake) is in INIT in d + 1, spends c cycles
//     in INIT .. POP (its cost), is in OUT in d + 1 + c, hands the result over in that cycle
//     (result_valid is clear), is IDLE again in d + 2 + c, and result_valid[core] is set from
//     d + 2 + c until the host takes it in the first cycle whose result_select names the core.
#include <catch2/catch.hpp>

#include <map>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "inputs/camera.h"
#include "kind_fixture.h"
#include "kinds/svo/golden_model.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/ray_setup.h"
#include "kinds/svo/svo_builder.h"
#include "reference/rtl_cycle_model.h"
#include "svo_descriptor.h"
#include "three_balls_scene.h"

using namespace rtu;

namespace {

// Tiny trees of test_traversal_costs.cpp in one image; a job picks one by its root address. Child
// pointers are relative, so each tree works wherever it is placed.
struct Tree {
  uint32_t root;
  uint32_t cost;  // of the centre-line job, by hand in test_traversal_costs.cpp
};
constexpr Tree kFullRoot{0, 2};     // INIT EVAL(hit)
constexpr Tree kEmptyRoot{1, 5};    // INIT EVAL NEXT EVAL NEXT
constexpr Tree kOnePush{2, 7};      // INIT EVAL NEXT EVAL PUSH INIT EVAL
constexpr Tree kPopBack{4, 14};     // pops back to the root once, then descends into child 7
constexpr Tree kFiveLevels{7, 17};  // INIT EVAL, then PUSH INIT EVAL for each of five levels

std::vector<uint32_t> treeImage() {
  std::vector<uint32_t> image = {
      descriptor(false, 0, 0xFF, 0xFF),                                     // kFullRoot
      descriptor(false, 0, 0x00, 0x00),                                     // kEmptyRoot
      descriptor(false, 1, 0x80, 0x00), descriptor(false, 0, 0x01, 0x01),   // kOnePush
      descriptor(false, 1, 0x88, 0x00), descriptor(false, 0, 0x02, 0x02),   // kPopBack
      descriptor(false, 0, 0x01, 0x01), descriptor(false, 1, 0xFF, 0x00)};  // kFiveLevels
  for (int level = 1; level <= 5; ++level)
    for (uint32_t slot = 0; slot < 8; ++slot)
      image.push_back(level < 5 ? descriptor(false, 8 - slot, 0xFF, 0x00)
                                : descriptor(false, 0, 0xFF, 0xFF));
  return image;
}

// The centre-line job of test_traversal_costs.cpp: t0 = (-8, -8, 2), t1 = (8, 8, 4).
TValueRecord centreLineJob(uint32_t id, const Tree& tree) {
  TValueRecord job;
  job.id = id;
  job.t0Bits = {floatBits(-8.0f), floatBits(-8.0f), floatBits(2.0f)};
  job.t1Bits = {floatBits(8.0f), floatBits(8.0f), floatBits(4.0f)};
  job.root = tree.root;
  return job;
}

std::vector<TValueRecord> centreLineJobs(const std::vector<Tree>& trees) {
  std::vector<TValueRecord> jobs;
  for (const Tree& tree : trees)
    jobs.push_back(centreLineJob(static_cast<uint32_t>(jobs.size()), tree));
  return jobs;
}

RtlTopRun runTrees(const std::vector<Tree>& trees, int cores) {
  const std::vector<uint32_t> image = treeImage();
  const std::vector<TValueRecord> jobs = centreLineJobs(trees);
  // The premise of every hand count: the golden model agrees with the hand-worked costs.
  GoldenModel golden(WordMemory(image), GoldenConfig{});
  for (size_t i = 0; i < jobs.size(); ++i) REQUIRE(golden.trace(jobs[i]).cost == trees[i].cost);
  RtlTopConfig config;
  config.cores = cores;
  return runRtlTop(WordMemory(image), jobs, config);
}

std::vector<uint32_t> resultIds(const RtlTopRun& run) {
  std::vector<uint32_t> ids;
  for (const CoreKindResult& result : run.results) ids.push_back(svoResult(result).id());
  return ids;
}

using Cycles = std::vector<uint64_t>;

}  // namespace

TEST_CASE("One job on one core takes 9 + cost cycles", "[rtl]") {
  // Accepted in 0, job manager out_valid in 6, core 0 takes it in 6 (core_select is always 0),
  // INIT in 7, OUT in 7 + c, result_valid[0] in 8 + c, taken by the host in 8 + c: 9 + c cycles.
  const RtlTopRun hit = runTrees({kFullRoot}, 1);  // c = 2
  REQUIRE(hit.acceptCycles == Cycles{0});
  REQUIRE(hit.dispatchCycles == Cycles{6});
  REQUIRE(hit.resultCycles == Cycles{10});
  REQUIRE(hit.totalCycles == 11);
  REQUIRE(hit.results.size() == 1);
  REQUIRE(resultHit(hit.results[0]));
  REQUIRE(resultCost(hit.results[0]) == 2);

  const RtlTopRun deep = runTrees({kFiveLevels}, 1);  // c = 17
  REQUIRE(deep.dispatchCycles == Cycles{6});
  REQUIRE(deep.resultCycles == Cycles{25});
  REQUIRE(deep.totalCycles == 26);
}

TEST_CASE("With 16 cores the result waits for result_select to come round", "[rtl]") {
  // Dispatched in 6 to core 6 (core_select = 6). result_valid[6] is set from 8 + c, and the host
  // sees it in the first cycle from then on with result_select = 6: 22 or 38.
  SECTION("c = 2: valid from 10, taken in 22") {
    const RtlTopRun run = runTrees({kFullRoot}, 16);
    REQUIRE(run.dispatchCycles == Cycles{6});
    REQUIRE(run.resultCycles == Cycles{22});
    REQUIRE(run.totalCycles == 23);
  }
  SECTION("c = 14: valid from 22, taken at once") {
    const RtlTopRun run = runTrees({kPopBack}, 16);
    REQUIRE(run.resultCycles == Cycles{22});
    REQUIRE(run.totalCycles == 23);
  }
  SECTION("c = 17: valid from 25, taken in 38") {
    const RtlTopRun run = runTrees({kFiveLevels}, 16);
    REQUIRE(run.resultCycles == Cycles{38});
    REQUIRE(run.totalCycles == 39);
  }
}

TEST_CASE("Jobs queue behind the one busy core", "[rtl]") {
  // Costs 2, 7, 5. Accepted in 0, 1, 2. Job 0: dispatched in 6, OUT in 9, core IDLE in 10.
  // Job 1 reaches the job manager output in 7 and stalls (core 0 in INIT) until 10: dispatched in
  // 10, OUT in 18, IDLE in 19. Job 2 moved to the output on the 10 edge and is dispatched in 19,
  // OUT in 25. Each result is taken the cycle after OUT: 10, 19, 26; total 27.
  const RtlTopRun run = runTrees({kFullRoot, kOnePush, kEmptyRoot}, 1);
  REQUIRE(run.acceptCycles == Cycles{0, 1, 2});
  REQUIRE(run.dispatchCycles == Cycles{6, 10, 19});
  REQUIRE(run.resultCycles == Cycles{10, 19, 26});
  REQUIRE(run.totalCycles == 27);
  REQUIRE(resultIds(run) == std::vector<uint32_t>{0, 1, 2});
}

TEST_CASE("A stalled job manager holds the host off", "[rtl]") {
  // Eight jobs of cost 2 on one core. Each holds the core for 4 cycles (IDLE handshake, INIT,
  // EVAL, OUT), so job k is dispatched in 6 + 4k and taken by the host in 10 + 4k. Jobs 0 to 6
  // are accepted in 0 to 6 (out_valid is low until 6, and in 6 the core takes job 0). In 7 job 1
  // waits at the output while core 0 is in INIT: pipeline_enable and in_ready are low, and the
  // full pipeline only moves in dispatch cycles, so job 7 is accepted with job 1's dispatch in 10.
  const RtlTopRun run = runTrees(std::vector<Tree>(8, kFullRoot), 1);
  REQUIRE(run.acceptCycles == Cycles{0, 1, 2, 3, 4, 5, 6, 10});
  REQUIRE(run.dispatchCycles == Cycles{6, 10, 14, 18, 22, 26, 30, 34});
  REQUIRE(run.resultCycles == Cycles{10, 14, 18, 22, 26, 30, 34, 38});
  REQUIRE(run.totalCycles == 39);
}

TEST_CASE("Two cores take jobs in turn", "[rtl]") {
  SECTION("cost 2") {
    // Job 0 to core 0 in 6, job 1 to core 1 in 7. Job 2 waits from 8: core 0 is OUT in 9 and
    // IDLE in 10, when core_select is 0 again: dispatched in 10. Results: core 0 valid from 10,
    // taken in 10 (result_select 0); core 1 OUT in 10, valid from 11, taken in 11 (select 1);
    // job 2 OUT in 13, valid from 14, taken in 14.
    const RtlTopRun run = runTrees({kFullRoot, kFullRoot, kFullRoot}, 2);
    REQUIRE(run.dispatchCycles == Cycles{6, 7, 10});
    REQUIRE(run.resultCycles == Cycles{10, 11, 14});
    REQUIRE(run.totalCycles == 15);
  }
  SECTION("cost 5") {
    // Core 0 is OUT in 12 and IDLE from 13, but 13 selects core 1 (OUT in 13), so job 2 goes to
    // core 0 in 14. Job 0 valid from 13, taken in 14 (select 0); job 1 valid from 14, taken in 15;
    // job 2 OUT in 20, valid from 21, taken in 22 (select 0).
    const RtlTopRun run = runTrees({kEmptyRoot, kEmptyRoot, kEmptyRoot}, 2);
    REQUIRE(run.dispatchCycles == Cycles{6, 7, 14});
    REQUIRE(run.resultCycles == Cycles{14, 15, 22});
    REQUIRE(run.totalCycles == 23);
    REQUIRE(resultIds(run) == std::vector<uint32_t>{0, 1, 2});
  }
}

TEMPLATE_LIST_TEST_CASE("Every ray's result equals the golden model's, whatever the core count",
                        "[rtl]", TestedKinds) {
  using Fixture = KindFixture<TestType>;
  const RtuConfig thesis = kindConfig<TestType>();
  RtuConfig other = thesis;  // other arithmetic and a stack shallow enough to overflow
  Fixture::otherArithmetic(other);

  for (const std::string& scene : Fixture::scenes()) {
    const auto frame = Fixture::frame(scene, 6, 32, 24);
    const auto& jobs = frame.jobs;
    for (RtuConfig config : {thesis, other}) {
      const std::vector<CoreKindResult> expected = Fixture::golden(frame.memory(), config, jobs);
      for (int cores : {1, 2, 4, 16}) {
        config.cores = cores;
        INFO(scene << ", " << config.coreConfig<SvoKind>().format.describe() << ", "
                   << config.coreConfig<SvoKind>().stackFrames << " frames, " << cores << " cores");
        const RtlTopRun run = runRtlTop(frame.memory(), jobs, rtlTopConfig(config));
        REQUIRE(run.results.size() == jobs.size());
        REQUIRE(run.resultCycles.size() == jobs.size());

        // Frame job ids are the job indices: each must come back exactly once, as golden says.
        std::map<uint32_t, size_t> position;
        for (size_t i = 0; i < run.results.size(); ++i)
          position[resultIdWord(run.results[i]) & TValueRecord::kMaxId] = i;
        REQUIRE(position.size() == jobs.size());
        for (size_t job = 0; job < jobs.size(); ++job) {
          REQUIRE(position.count(static_cast<uint32_t>(job)) == 1);
          const size_t i = position[static_cast<uint32_t>(job)];
          REQUIRE(run.results[i] == expected[job]);
          // Into core (dispatch mod cores), out through result_select = the same core; the core
          // is busy for its IDLE handshake, the cost and OUT before the result can leave.
          const uint64_t dispatch = run.dispatchCycles[job];
          const uint64_t out = run.resultCycles[i];
          REQUIRE(dispatch >= run.acceptCycles[job] + 6);
          REQUIRE(out >= dispatch + resultCost(expected[job]) + 2);
          REQUIRE((out - dispatch) % static_cast<uint64_t>(cores) == 0);
        }
        // The job manager is a FIFO and every handshake takes a cycle.
        for (size_t job = 1; job < jobs.size(); ++job) {
          REQUIRE(run.acceptCycles[job] > run.acceptCycles[job - 1]);
          REQUIRE(run.dispatchCycles[job] > run.dispatchCycles[job - 1]);
          REQUIRE(run.resultCycles[job] > run.resultCycles[job - 1]);
        }
        REQUIRE(run.totalCycles == run.resultCycles.back() + 1);
        if (cores == 1) {
          // The pipeline is full while the core works, so each job holds the core for its cost
          // + 2 cycles back to back, starting with the first job's dispatch (in 6 for a t-value
          // record), and the last result leaves one cycle later.
          const uint64_t busy = std::accumulate(expected.begin(), expected.end(), uint64_t{0},
                                                [](uint64_t sum, const CoreKindResult& r) {
                                                  return sum + resultCost(r) + 2;
                                                });
          REQUIRE(run.totalCycles == Fixture::firstDispatch(config.jobManager) + busy + 1);
        }
      }
    }
  }
}

TEST_CASE("Ray records: the ray stages, and a model's first ray waits for its header", "[rtl]") {
  // One core, 6 + 6 stages, 16 cycles of header fetch. Ray 0 (instance 0) is taken in 0 and
  // fetches the header in 1 .. 16, so ray 1 (instance 0 again) is taken in 17 and ray 2 (instance
  // 1, a header of its own) in 18, fetching in 19 .. 34. Ray 0 reaches the output in
  // 0 + 12 + 16 = 28 and goes to the idle core; ray 1 reaches it in 17 + 12 = 29 and waits for
  // the core until 30 + W0, a stall of 1 + W0 cycles that holds ray 2 too: 18 + 12 + 16 + 1 + W0.
  const ThreeBalls scene;
  const RayRecord ray = frameRays(3, 3)[4];
  std::vector<HostRecord> records;
  for (size_t instance : {0, 0, 1}) {
    RayRecord record = ray;
    record.modelAddress = scene.instances[instance].headerAddress;
    records.push_back(record);
  }
  RtlTopConfig config;
  config.cores = 1;
  const RtlTopRun run = runRtlTop(scene.memory.memory(), records, config);
  REQUIRE(run.results.size() == 3);
  const uint64_t w0 = resultCost(run.results[0]), w1 = resultCost(run.results[1]);
  CHECK(run.acceptCycles == Cycles{0, 17, 18});
  CHECK(run.dispatchCycles == Cycles{28, 30 + w0, std::max(47 + w0, 32 + w0 + w1)});
}

TEST_CASE("No jobs take no cycles", "[rtl]") {
  const RtlTopRun run = runRtlTop(WordMemory(), std::vector<TValueRecord>{}, RtlTopConfig{});
  REQUIRE(run.results.empty());
  REQUIRE(run.totalCycles == 0);
}

TEST_CASE("Impossible configurations are rejected", "[rtl]") {
  const std::vector<TValueRecord> jobs = centreLineJobs({kFullRoot});
  const WordMemory memory;
  RtlTopConfig config;
  for (int cores : {0, -1, kMaxRtlCores + 1}) {
    config.cores = cores;
    REQUIRE_THROWS_AS(runRtlTop(memory, jobs, config), std::invalid_argument);
  }
  config = RtlTopConfig{};
  config.coreConfig<SvoKind>().stackFrames = 0;
  REQUIRE_THROWS_AS(runRtlTop(memory, jobs, config), std::invalid_argument);
  config = RtlTopConfig{};
  config.coreConfig<SvoKind>().format = FixedFormat{64, 16};
  REQUIRE_THROWS_AS(runRtlTop(memory, jobs, config), std::invalid_argument);
  config = RtlTopConfig{};
  config.cores = kMaxRtlCores;
  REQUIRE_NOTHROW(config.validate());
}
