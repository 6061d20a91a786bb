// The recurrence of src/rtu/rtu_recurrence.h: on cases counted by hand, against the naive RTL
// transcription, and (through src/run/analytic_run.h) against the SystemC model in every
// configuration it claims to model, statistics included.

#include <catch2/catch.hpp>

#include "inputs/camera.h"
#include "kind_fixture.h"
#include "kinds/svo/svo_image.h"
#include "reference/rtl_cycle_model.h"
#include "rtu/rtu_recurrence.h"
#include "run/analytic_run.h"

namespace rtu {
namespace {

std::vector<JobTiming> jobsOfCost(std::vector<uint64_t> costs) {
  std::vector<JobTiming> jobs;
  for (uint64_t cost : costs) jobs.push_back(JobTiming{cost, 6, 0});
  return jobs;
}

RecurrenceConfig onCores(int cores) {
  RecurrenceConfig config;
  config.cores = cores;
  return config;
}

// A small frame's t-value records, and its rays as ray records against a model header.
template <class Kind>
struct RecordFrame {
  typename KindFixture<Kind>::Frame frame;
  std::vector<HostRecord> tValueRecords, rayRecords;
};

template <class Kind>
RecordFrame<Kind> smallFrame(const std::string& scene) {
  using Fixture = KindFixture<Kind>;
  RecordFrame<Kind> records{Fixture::frame(scene, 5, 20, 12), {}, {}};
  records.tValueRecords.assign(records.frame.jobs.begin(), records.frame.jobs.end());
  records.rayRecords = Fixture::rayRecords(records.frame, 20, 12);
  return records;
}

nlohmann::ordered_json withoutHostTime(nlohmann::ordered_json statistics) {
  statistics.erase("simulation");
  return statistics;
}

}  // namespace

TEST_CASE("Recurrence on one core, counted by hand", "[recurrence]") {
  // Job 0: accepted 0, pending 6 (6 stages), dispatched 6, OUT from 12 (INIT in 7, 5 states),
  // handed over 12, buffered from 13 and drained 13. Job 1: accepted 1, pending 7, waits for the
  // core to be idle in 13; its result is handed over 19 (the buffer is free from 14) and drained
  // 20. Job 2: accepted 2, held 6 cycles behind job 1's stall: pending 14, dispatched 20.
  const RecurrenceRun run = runRecurrence(jobsOfCost({5, 5, 5}), onCores(1));
  CHECK(run.acceptCycles == std::vector<uint64_t>{0, 1, 2});
  CHECK(run.pendingCycles == std::vector<uint64_t>{6, 7, 14});
  CHECK(run.dispatchCycles == std::vector<uint64_t>{6, 13, 20});
  CHECK(run.handoverCycles == std::vector<uint64_t>{12, 19, 26});
  CHECK(run.drainCycles == std::vector<uint64_t>{13, 20, 27});
  CHECK(run.totalCycles == 28);
}

TEST_CASE("Recurrence: a full pipeline stalls the host", "[recurrence]") {
  // One core, eight jobs of cost 20: jobs 0..5 enter in cycles 0..5 and job 6 in 6 (job 0 leaves
  // in 6); job 1 then waits at the output from 7 to 28 (job 0's core is idle from 28), so job 7
  // enters only in 28.
  const RecurrenceRun run = runRecurrence(jobsOfCost(std::vector<uint64_t>(8, 20)), onCores(1));
  CHECK(run.acceptCycles == std::vector<uint64_t>{0, 1, 2, 3, 4, 5, 6, 28});
  CHECK(run.dispatchCycles[1] == 28);
}

TEST_CASE("Recurrence: two cores under cfa take turns with the select counter", "[recurrence]") {
  // Job 0 pends in 6 (core 0 selected: 6 mod 2 = 0), job 1 in 7 (core 1), job 2 in 8 (core 0,
  // busy until its handover in 6 + 1 + 10 = 17; idle from 18, an even cycle).
  const RecurrenceRun run = runRecurrence(jobsOfCost({10, 10, 1}), onCores(2));
  CHECK(run.dispatchCycles == std::vector<uint64_t>{6, 7, 18});
  CHECK(run.cores == std::vector<int>{0, 1, 0});
  // Buffered from 18 and 19; core 0 is selected in even cycles, core 1 in odd ones.
  CHECK(run.drainCycles == std::vector<uint64_t>{18, 19, 22});
}

TEMPLATE_LIST_TEST_CASE("Recurrence equals the RTL transcription in the thesis configuration",
                        "[recurrence]", TestedKinds) {
  for (const std::string& scene : KindFixture<TestType>::scenes()) {
    const RecordFrame<TestType> records = smallFrame<TestType>(scene);
    const auto& frame = records.frame;
    for (bool other : {false, true}) {  // the kind's other settings too
      for (int cores : {1, 3, 16}) {
        RtuConfig config = kindConfig<TestType>();
        if (other) KindFixture<TestType>::otherArithmetic(config);
        config.cores = cores;
        const RtuRun analytic = runAnalytic(frame.memory(), frame.jobs, config);
        const RtlTopRun rtl = runRtlTop(frame.memory(), frame.jobs, rtlTopConfig(config));
        INFO(scene << ", " << cores << " cores" << (other ? ", other settings" : ""));
        checkEqualsRtl(analytic, rtl);
      }
    }
  }
}

TEMPLATE_LIST_TEST_CASE("Recurrence equals the SystemC model, statistics included", "[recurrence]",
                        TestedKinds) {
  const auto scene = GENERATE_COPY(from_range(KindFixture<TestType>::scenes()));
  const RecordFrame<TestType> records = smallFrame<TestType>(scene);
  const auto policy = GENERATE(SchedulerPolicy::CyclicFirstAvailable, SchedulerPolicy::RoundRobin,
                               SchedulerPolicy::FirstAvailable);
  const int cores = GENERATE(1, 4, 16);
  const auto links = GENERATE(std::pair<double, double>{0, 0}, std::pair<double, double>{8, 0},
                              std::pair<double, double>{0, 8}, std::pair<double, double>{3, 5},
                              std::pair<double, double>{32, 2.5});
  const bool rays = GENERATE(false, true);
  RtuConfig config = kindConfig<TestType>();
  config.cores = cores;
  config.scheduler = policy;
  config.hostInput.bytesPerCycle = links.first;
  config.hostOutput.bytesPerCycle = links.second;
  const std::vector<HostRecord>& hostRecords = rays ? records.rayRecords : records.tValueRecords;
  const WordMemory memory = records.frame.memory();
  const RtuRun analytic = runAnalytic(memory, hostRecords, config);
  const RtuRun simulated = simulateRtu(memory, hostRecords, config);
  INFO(scene << ", " << toString(policy) << ", " << cores << " cores, links " << links.first << "/"
             << links.second << (rays ? ", ray records" : ", t-value records"));
  CHECK(analytic.totalCycles == simulated.totalCycles);
  CHECK(analytic.arrivalCycles == simulated.arrivalCycles);
  CHECK(analytic.jobIndices == simulated.jobIndices);
  CHECK(analytic.results == simulated.results);
  CHECK(withoutHostTime(analytic.statistics.toJson()) ==
        withoutHostTime(simulated.statistics.toJson()));
}

TEST_CASE("The recurrence refuses what it cannot model", "[recurrence]") {
  RtuConfig config;
  CHECK_FALSE(whyNotAnalytic(config));
  config.memory.ideal = false;
  CHECK(whyNotAnalytic(config) == std::string("the memory is cached"));
  config = RtuConfig{};
  config.reorderCapacity = 4;
  CHECK(whyNotAnalytic(config));
  config = RtuConfig{};
  config.hostOutput.activeProbability = 0.5;
  CHECK(whyNotAnalytic(config));
  REQUIRE_THROWS_WITH(runAnalytic(SvoImage{}.memory(), std::vector<TValueRecord>{}, config),
                      Catch::Contains("randomly inactive"));
}

TEST_CASE("Result records over 32 bits take 48 bytes on a paced output link", "[recurrence]") {
  // 16 cores finish results faster than an 8-byte-a-cycle link drains them, so consecutive
  // results reach the host one record's slot apart: 32 / 8 = 4 cycles at 32 bits, 48 / 8 = 6 at 40.
  const RecordFrame<SvoKind> records = smallFrame<SvoKind>("sphere");
  const WordMemory memory = records.frame.memory();
  for (const auto& [format, gap] :
       {std::pair{FixedFormat{32, 16}, 4ull}, std::pair{FixedFormat{40, 24}, 6ull}}) {
    RtuConfig config;
    config.cores = 16;
    config.hostOutput.bytesPerCycle = 8;
    config.coreConfig<SvoKind>().format = format;
    const RtuRun simulated = simulateRtu(memory, records.tValueRecords, config);
    uint64_t smallest = ~0ull;
    for (size_t i = 1; i < simulated.arrivalCycles.size(); ++i)
      smallest = std::min(smallest, simulated.arrivalCycles[i] - simulated.arrivalCycles[i - 1]);
    CHECK(smallest == gap);
    CHECK(runAnalytic(memory, records.tValueRecords, config).arrivalCycles ==
          simulated.arrivalCycles);
  }
}

}  // namespace rtu
