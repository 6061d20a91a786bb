// Statistics declared once (src/base/statistics.h): every key written comes from a declaration,
// and windows, sums over cores, frames and rows follow the declarations, by hand-derived values.

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "explore/animation_run.h"
#include "explore/exploration_run.h"
#include "explore/ray_passes.h"
#include "run/rtu_statistics.h"
#include "run/sampled_run.h"
#include "run/statistics_output.h"
#include "run/statistics_window.h"

namespace rtu {
namespace {

using Json = nlohmann::ordered_json;

std::set<std::string> declaredKeys(const std::vector<Statistic>& statistics) {
  std::set<std::string> keys;
  for (const Statistic& statistic : statistics) {
    INFO(statistic.key);
    CHECK(keys.insert(statistic.key).second);  // declared once
    CHECK_FALSE(statistic.doc.empty());
  }
  return keys;
}

// The keys of `json`: a declared key is a leaf (a histogram, an interval), parts of an array are
// "*"; anything else is walked into.
void writtenKeys(const Json& json, const std::string& key, const std::set<std::string>& declared,
                 std::set<std::string>& keys) {
  if (!key.empty() && (declared.count(key) || !json.is_structured())) {
    keys.insert(key);
    return;
  }
  const std::string prefix = key.empty() ? "" : key + "/";
  if (json.is_array())
    for (const Json& part : json) writtenKeys(part, prefix + "*", declared, keys);
  else
    for (const auto& [name, value] : json.items())
      writtenKeys(value, prefix + name, declared, keys);
}

std::set<std::string> writtenKeys(const Json& json, const std::set<std::string>& declared) {
  std::set<std::string> keys;
  writtenKeys(json, "", declared, keys);
  return keys;
}

// A run with every optional part: cached memory, two cores, a scene, a reorder buffer.
RtuStatistics everything() {
  RtuStatistics s;
  s.rays = 10;
  s.totalCycles = 200;
  s.cores = 2;
  s.scheduler = "cfa";
  s.idealMemory = false;
  s.coreTimes.resize(2);
  s.l1.resize(2);
  s.waitHistogram = {{0, 8}, {3, 2}};
  s.reorderMaxOccupancy = 4;
  s.scene = SceneManagerStatistics{};
  s.scene->jobsPerRay = {{1, 6}, {2, 4}};
  return s;
}

TEST_CASE("Every key of a run's statistics JSON is declared, once", "[statistics]") {
  const std::set<std::string> declared = declaredKeys(RtuStatistics::declaration().statistics());
  // Each kind's run writes its own counters: over the runs of every kind, every key.
  std::set<std::string> overKinds;
  for (const std::string& core : CoreKinds::names()) {
    RtuStatistics run = everything();
    run.core = core;
    const std::set<std::string> keys = writtenKeys(run.toJson(), declared);
    overKinds.insert(keys.begin(), keys.end());
  }
  CHECK(overKinds == declared);
  // Without the optional parts their keys are not written.
  RtuStatistics ideal;
  ideal.coreTimes.resize(1);
  std::set<std::string> written = writtenKeys(ideal.toJson(), declared);
  for (const std::string& key : written) CHECK(declared.count(key));
  CHECK_FALSE(written.count("memory/l1/hits"));
  CHECK_FALSE(written.count("cores/*/l1/hits"));
  CHECK_FALSE(written.count("scene_manager/rays"));
  CHECK_FALSE(written.count("reorder_buffer/max_occupancy"));
}

TEST_CASE("Every key of the sample, a frame and the CSV columns is declared", "[statistics]") {
  SampledRun sampled;
  sampled.plan.rays = 100;
  sampled.counted.idealMemory = false;
  const std::set<std::string> sample = declaredKeys(SampledRun::declaration().statistics());
  CHECK(writtenKeys(statisticsJson(sampled), sample) == sample);

  const std::set<std::string> frame = declaredKeys(FrameStatistics::declaration().statistics());
  CHECK(writtenKeys(statisticsJson(FrameStatistics{}), frame) == frame);
  const std::vector<std::string> header = statisticsHeader<FrameStatistics>();
  CHECK(header.size() == frame.size() - 1);  // all but the clock
  CHECK(std::find(header.begin(), header.end(), "clock_mhz") == header.end());
  CHECK(statisticsFields(FrameStatistics{}, "%g").size() == header.size());

  // fps and sweep columns name declared statistics (an interval's end by its index; a pass's
  // figure as passes/<pass>/<figure>).
  const std::set<std::string> run = declaredKeys(RtuStatistics::declaration().statistics());
  const std::set<std::string> pass = declaredKeys(FramePass::declaration().statistics());
  for (const auto& [column, key] : statisticsColumnKeys()) {
    INFO(column);
    const std::string statistic =
        key.back() == '0' || key.back() == '1' ? key.substr(0, key.rfind('/')) : key;
    const bool inSample = statistic.rfind("sample/", 0) == 0 && sample.count(statistic.substr(7));
    const bool inPass = statistic.rfind("passes/", 0) == 0 &&
                        pass.count(statistic.substr(statistic.rfind('/') + 1));
    CHECK((run.count(statistic) || inSample || inPass));
  }
}

// A core's statistics: its kind's counters are a base class, so no aggregate initialisation.
CoreStatistics coreStatistics(uint64_t jobs, uint64_t busy, uint64_t blocked, uint64_t out,
                              uint64_t stackOverflows, uint64_t tOverflows) {
  CoreStatistics core;
  core.jobs = jobs, core.busyCycles = busy, core.blockedCycles = blocked, core.outCycles = out;
  core.stackOverflows = stackOverflows, core.tOverflows = tOverflows;
  return core;
}

TEST_CASE("A window subtracts counters and histograms and keeps the whole run's maxima",
          "[statistics]") {
  RtuStatistics whole = everything(), prefix = everything();
  whole.coreTimes[0] = coreStatistics(10, 100, 20, 5, 3, 1);
  prefix.coreTimes[0] = coreStatistics(4, 30, 5, 2, 1, 1);
  whole.l1[1] = CacheStats{50, 40, 2, 8, 1};
  prefix.l1[1] = CacheStats{20, 15, 1, 4, 0};
  whole.l2.cache = CacheStats{9, 5, 1, 3, 2};
  prefix.l2.cache = CacheStats{4, 2, 0, 2, 0};
  whole.l2.dram = {3, 192, 24};
  prefix.l2.dram = {2, 128, 16};
  whole.l2.portQueueCycles = 7, prefix.l2.portQueueCycles = 2;
  whole.maxWait = 9, prefix.maxWait = 3;
  whole.maxCost = 60, prefix.maxCost = 80;  // a prefix may not exceed the whole; kept anyway
  whole.totalCost = 500, prefix.totalCost = 120;
  whole.belowResolution = 4, prefix.belowResolution = 1;
  whole.scene->rays = 10, prefix.scene->rays = 4;
  whole.scene->jobsPerRay = {{1, 6}, {2, 4}};
  prefix.scene->jobsPerRay = {{1, 2}, {2, 2}};
  prefix.waitHistogram = {{0, 5}, {3, 2}};

  const RtuStatistics part = statisticsAfter(whole, prefix, 6, 120);
  CHECK(part.rays == 6);
  CHECK(part.totalCycles == 120);
  const CoreStatistics& core = part.coreTimes[0];
  CHECK((core.jobs == 6 && core.busyCycles == 70 && core.blockedCycles == 15 &&
         core.outCycles == 3 && core.stackOverflows == 2 && core.tOverflows == 0));
  CHECK((part.l1[1].accesses == 30 && part.l1[1].hits == 25 && part.l1[1].merged == 1 &&
         part.l1[1].misses == 4 && part.l1[1].evictions == 1));
  CHECK((part.l2.cache.accesses == 5 && part.l2.cache.hits == 3 && part.l2.cache.evictions == 2));
  CHECK((part.l2.dram.reads == 1 && part.l2.dram.bytes == 64 && part.l2.dram.busyCycles == 8));
  CHECK(part.l2.portQueueCycles == 5);
  CHECK(part.waitHistogram == Histogram{{0, 3}});  // an emptied bin is gone
  CHECK(part.maxWait == 9);
  CHECK(part.maxCost == 60);
  CHECK(part.totalCost == 380);
  CHECK(part.belowResolution == 3);
  CHECK(part.scene->rays == 6);
  CHECK(part.scene->jobsPerRay == Histogram{{1, 4}, {2, 2}});
  CHECK(part.scheduler == "cfa");  // settings stay
  CHECK_FALSE(part.idealMemory);
}

TEST_CASE("Sums over cores, rows and frames", "[statistics]") {
  RtuStatistics run = everything();
  run.coreTimes = {coreStatistics(3, 30, 6, 2, 1, 0), coreStatistics(4, 41, 7, 3, 0, 2)};
  run.l1 = {CacheStats{10, 7, 1, 2, 0}, CacheStats{20, 12, 3, 5, 1}};
  const CoreStatistics cores = run.allCores();
  CHECK((cores.jobs == 7 && cores.busyCycles == 71 && cores.blockedCycles == 13 &&
         cores.outCycles == 5 && cores.stackOverflows == 1 && cores.tOverflows == 2));
  const CacheStats l1 = run.allL1();
  CHECK((l1.accesses == 30 && l1.hits == 19 && l1.merged == 4 && l1.misses == 7 &&
         l1.evictions == 1));
  // Counted per core, written once for the run; a report line each when not 0.
  const Json json = run.toJson();
  CHECK(json["stack_overflows"] == 1);
  CHECK(json["t_overflows"] == 2);
  CHECK_FALSE(json["cores"][0].contains("stack_overflows"));
  CHECK(json["cores"][1]["idle"] == 200 - (41 + 7 + 3));
  CHECK(json["cores"][1]["l1"]["hit_rate"] == Approx(15.0 / 20));
  CHECK(json["memory"]["l1"]["accesses"] == 30);
  std::ostringstream report;
  writeReportedLines(report, run);
  CHECK(report.str() == "stack overflows: 1 rays\n"
                        "t overflows: 2 rays (t-values beyond the fixed-point range; flag 2)\n");

  // Rows (sampled blocks): the first one's settings, counters added, maxima the largest.
  RtuStatistics a = everything(), b = everything();
  a.rays = 3, b.rays = 4;
  a.totalCycles = 30, b.totalCycles = 50;
  a.coreTimes[1].busyCycles = 11, b.coreTimes[1].busyCycles = 5;
  a.maxWait = 2, b.maxWait = 7;
  a.maxBlocked = 9, b.maxBlocked = 1;
  a.waitHistogram = {{0, 1}, {2, 2}}, b.waitHistogram = {{2, 1}, {5, 3}};
  a.hostSeconds = 0.25, b.hostSeconds = 0.5;
  b.scheduler = "rr";
  RtuStatistics rows;
  addStatistics(rows, a);
  addStatistics(rows, b);
  CHECK(rows.rays == 7);
  CHECK(rows.totalCycles == 80);
  CHECK(rows.coreTimes[1].busyCycles == 16);
  CHECK(rows.maxWait == 7);
  CHECK(rows.maxBlocked == 9);
  CHECK(rows.waitHistogram == Histogram{{0, 1}, {2, 3}, {5, 3}});
  CHECK(rows.hostSeconds == 0.75);
  CHECK(rows.scheduler == "cfa");

  // Frames: counters added, the first frame's number, time and clock.
  FrameStatistics f0, f1;
  f0.frame = 4, f1.frame = 5;
  f0.time = 0.5, f1.time = 0.625;
  f0.pixels = f1.pixels = 100;
  f0.raysTraced = 100, f1.raysTraced = 30;
  f0.raysSaved = 0, f1.raysSaved = 70;
  f0.jobs = 150, f1.jobs = 40;
  f0.cycles = 900, f1.cycles = 300;
  f0.hostSeconds = 0.5, f1.hostSeconds = 0.25;
  f0.clockMhz = f1.clockMhz = 200;
  const FrameStatistics frames = sumOf(std::vector<FrameStatistics>{f0, f1});
  CHECK((frames.frame == 4 && frames.time == 0.5 && frames.clockMhz == 200));
  CHECK((frames.pixels == 200 && frames.raysTraced == 130 && frames.raysSaved == 70 &&
         frames.jobs == 190 && frames.cycles == 1200 && frames.hostSeconds == 0.75));
}

TEST_CASE("Utilisation of every resource, and the limit named with its value", "[statistics]") {
  // Two cores over 1000 cycles, 400 rays; cached memory.
  RtuStatistics run;
  run.totalCycles = 1000;
  run.rays = 400;
  run.cores = 2;
  run.idealMemory = false;
  run.coreTimes.resize(2);
  run.coreTimes[0].busyCycles = 900, run.coreTimes[1].busyCycles = 800;       // 1700 / 2000
  run.coreTimes[0].blockedCycles = 50, run.coreTimes[1].blockedCycles = 150;  // 200 / 2000
  run.l2.dram.busyCycles = 300;
  run.l2.cache.accesses = 500;
  run.hostInBytesPerCycle = 16.0;  // a 32-byte record in 2 cycles: 800 of 1000
  run.hostOutBytesPerCycle = 0.0;  // unlimited
  const RtuStatistics::Utilisation use = run.utilisation();
  CHECK(use.cores == Approx(0.85));
  CHECK(use.memoryLatency == Approx(0.1));
  CHECK(use.dramBandwidth == Approx(0.3));
  CHECK(use.l2Port == Approx(0.5));
  CHECK(use.hostIn == Approx(0.8));
  CHECK(use.hostOut == 0.0);
  CHECK(use.jobManager == Approx(0.4));
  CHECK(run.limit() == "cores");
  CHECK(run.limitUtilisation() == Approx(0.85));
  // The input link 5 points behind or closer is named with it.
  CHECK(run.describeLimit() == "limited by cores (85.0 %; host_in 80.0 % close behind)");
  run.hostInBytesPerCycle = 32.0;
  CHECK(run.describeLimit() == "limited by cores (85.0 %)");
  // Below 0.8 nothing is saturated: limit "none", the highest still named in the report.
  run.coreTimes[0].busyCycles = 500;  // 1300 / 2000
  CHECK(run.limit() == "none");
  CHECK(run.limitUtilisation() == Approx(0.65));
  CHECK(run.describeLimit() == "nothing saturated (highest: cores 65.0 %)");
  // Written with the run: the limit, its value and every resource's.
  const Json json = run.toJson();
  CHECK(json["limit"] == "none");
  CHECK(json["utilisation"]["dram_bandwidth"] == Approx(0.3));
  CHECK(json["utilisation"]["l2_port"] == Approx(0.5));
}

TEST_CASE("A frame's statistics: its CSV row, and its worker line read back exactly",
          "[statistics]") {
  FrameStatistics frame;
  frame.frame = 3;
  frame.time = 0.1;
  frame.pixels = 64;
  frame.raysTraced = 40;
  frame.raysSaved = 24;
  frame.hits = 30;
  frame.jobs = 50;
  frame.culled = 7;
  frame.earlyTerminations = 2;
  frame.skipped = 3;
  frame.traversalCycles = 777;
  frame.cycles = 1000;
  frame.hostSeconds = 1.0 / 3;
  frame.clockMhz = 250;
  CHECK(statisticsFields(frame, "%.6g") ==
        std::vector<std::string>{"3", "0.1", "64", "40", "24", "30", "50", "1.25", "7", "2", "3",
                                 "777", "1000", "0.004", "250000", "0.333333"});
  FrameStatistics back;
  readStatistics(back, Json::parse(statisticsJson(frame).dump()));
  CHECK(statisticsJson(back) == statisticsJson(frame));
  CHECK(back.hostSeconds == frame.hostSeconds);
  CHECK(back.clockMhz == 250);
}

// A kind's own counters: a struct of its own, held by its core's statistics (an empty key puts
// them among the core's), counted per core; those marked runTotal() are written for the run.
struct KindCounters {
  uint64_t nodes = 0, restarts = 0;
  static const StatisticGroup<KindCounters>& declaration() {
    static const StatisticGroup<KindCounters> group =
        StatisticGroup<KindCounters>("a kind")
            .count(Statistic("nodes_visited", "nodes", "nodes a core visited"),
                   &KindCounters::nodes)
            .count(Statistic("restarts", "rays", "rays restarted").runTotal().reportedWhenNotZero(),
                   &KindCounters::restarts);
    return group;
  }
};
struct KindCore {
  uint64_t jobs = 0;
  KindCounters kind;
  static const StatisticGroup<KindCore>& declaration() {
    static const StatisticGroup<KindCore> group =
        StatisticGroup<KindCore>("a core")
            .count(Statistic("jobs", "jobs", "jobs taken"), &KindCore::jobs)
            .group(Statistic("", "", "the kind's counters"), &KindCore::kind);
    return group;
  }
};
struct KindRun {
  std::vector<KindCore> cores;
  static const StatisticGroup<KindRun>& declaration() {
    static const StatisticGroup<KindRun> group =
        StatisticGroup<KindRun>("a run").list(Statistic("cores", "", "per core"), &KindRun::cores);
    return group;
  }
};

TEST_CASE("A kind declares its own counters, they are written and combined generically",
          "[statistics]") {
  KindRun run;
  run.cores = {{2, {30, 1}}, {3, {45, 2}}};
  CHECK(statisticsJson(run).dump() ==
        R"({"cores":[{"jobs":2,"nodes_visited":30},{"jobs":3,"nodes_visited":45}],"restarts":3})");
  std::vector<std::string> keys;
  for (const Statistic& statistic : KindRun::declaration().statistics())
    keys.push_back(statistic.key);
  CHECK(keys == std::vector<std::string>{"cores/*/jobs", "cores/*/nodes_visited", "restarts"});
  std::ostringstream report;
  writeReportedLines(report, run);
  CHECK(report.str() == "restarts: 3 rays\n");
  KindRun before = run;
  before.cores[1].kind.nodes = 40;
  subtractStatisticsOf(run, before);
  CHECK(run.cores[1].kind.nodes == 5);
  CHECK(run.cores[1].jobs == 0);
}

}  // namespace
}  // namespace rtu

namespace rtu {
namespace {

// The top-level keys of a run's statistics JSON whose names start with `prefix`, in order.
std::vector<std::string> topKeys(const Json& json, const std::string& prefix) {
  std::vector<std::string> keys;
  for (const auto& [key, value] : json.items())
    if (key.rfind(prefix, 0) == 0) keys.push_back(key);
  return keys;
}

// Two cores of a run of `core` with some of every kind's counters counted (a run counts only
// its own kind's; the others are set here to see that they are not written).
RtuStatistics twoCoresOf(const std::string& core) {
  RtuConfig config;
  config.core = core;
  RtuStatistics s = RtuStatistics::of(config);
  s.rays = 5;
  s.coreTimes = {coreStatistics(2, 10, 0, 1, 1, 0), coreStatistics(3, 20, 0, 1, 0, 2)};
  s.coreTimes[0].bvhNodesVisited = 30, s.coreTimes[1].bvhNodesVisited = 45;
  s.coreTimes[1].bihTriangleTests = 7;
  return s;
}

TEST_CASE("A run's statistics hold the counters of its cores' kind and no other kind's",
          "[statistics]") {
  const Json svo = twoCoresOf("svo").toJson();
  CHECK(topKeys(svo, "bvh_").empty());
  CHECK(topKeys(svo, "bih_").empty());
  CHECK(svo["stack_overflows"] == 1);
  CHECK(svo["t_overflows"] == 2);
  // As before the other kinds were registered: right after the cores, before below_resolution.
  const std::vector<std::string> all = topKeys(svo, "");
  const auto cores = std::find(all.begin(), all.end(), "cores");
  REQUIRE(cores + 5 < all.end());
  CHECK(std::vector<std::string>(cores + 1, cores + 6) ==
        std::vector<std::string>{"stack_overflows", "t_overflows", "any_hit_rays", "any_hit_hits",
                                 "below_resolution"});

  const Json bvh = twoCoresOf("bvh").toJson();
  CHECK(topKeys(bvh, "bvh_") ==
        std::vector<std::string>{"bvh_nodes_visited", "bvh_box_tests", "bvh_triangle_tests",
                                 "bvh_stack_overflows", "bvh_bytes_fetched", "bvh_any_hit_rays",
                                 "bvh_any_hit_hits", "bvh_instances"});
  CHECK(bvh["bvh_nodes_visited"] == 75);
  CHECK_FALSE(bvh.contains("stack_overflows"));
  CHECK_FALSE(bvh.contains("t_overflows"));
  CHECK(topKeys(bvh, "bih_").empty());

  const Json bih = twoCoresOf("bih").toJson();
  CHECK(topKeys(bih, "bih_") == std::vector<std::string>{"bih_nodes_visited", "bih_triangle_tests",
                                                         "bih_stack_overflows",
                                                         "bih_divider_errors", "bih_bytes_fetched",
                                                         "bih_any_hit_rays", "bih_any_hit_hits"});
  CHECK(bih["bih_triangle_tests"] == 7);
  CHECK(topKeys(bih, "bvh_").empty());
  CHECK_FALSE(bih.contains("stack_overflows"));

  // A window keeps the run's kind and subtracts its counters.
  RtuStatistics prefix = twoCoresOf("bvh");
  prefix.coreTimes[1].bvhNodesVisited = 40;
  const Json window = statisticsAfter(twoCoresOf("bvh"), prefix, 2, 10).toJson();
  CHECK(window["bvh_nodes_visited"] == 5);
  CHECK_FALSE(window.contains("stack_overflows"));

  // The fps and sweep CSV keep a column for every kind's counters (rows of several kinds share
  // one header); another kind's are empty in a row, not 0.
  const std::vector<std::string>& columns = statisticsColumns();
  const auto field = [&columns](const Json& statistics, const std::string& column) {
    const std::vector<std::string> values = statisticsValues(Json{{"statistics", statistics}});
    const auto at = std::find(columns.begin(), columns.end(), column);
    REQUIRE(at != columns.end());
    return values[static_cast<size_t>(at - columns.begin())];
  };
  CHECK(field(svo, "stack_overflows") == "1");
  CHECK(field(svo, "bvh_nodes_visited").empty());
  CHECK(field(bvh, "bvh_nodes_visited") == "75");
  CHECK(field(bvh, "stack_overflows").empty());
}

}  // namespace
}  // namespace rtu
