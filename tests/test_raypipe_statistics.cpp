// The ray pipe's statistics (raypipe/raypipe_statistics.h) of a hand-made run: totals, rates at the
// clock, each unit's utilisation of its full rate, the limit rule and the JSON's keys.
#include <catch2/catch.hpp>

#include "raypipe/raypipe_statistics.h"
#include "run/statistics_output.h"

namespace rtu {
namespace {

RaypipeCycleResult ray(bool hit, bool boxMiss, int64_t exit, KdRayCounts counts) {
  RaypipeCycleResult r;
  r.hit = hit;
  r.boxMiss = boxMiss;
  r.exitCycle = exit;
  r.counts = counts;
  return r;
}

// Three rays (a hit, a miss in the box, a box miss), the last leaving at cycle 150: 151 cycles.
RaypipeCycleRun handRun(int64_t travBusy) {
  RaypipeCycleRun run;
  KdRayCounts hit, miss;
  hit.nodes = 3, hit.leaves = 1, hit.triangleTests = 2, hit.pushes = 1;
  miss.nodes = 2, miss.leaves = 1, miss.triangleTests = 1, miss.dropped = 1, miss.restarts = 1;
  run.setResults({ray(true, false, 140, hit), ray(false, false, 150, miss),
                  ray(false, true, 70, KdRayCounts{})});
  run.units = {{"prg", 3, 0}, {"sint", 3, 5}, {"trav", travBusy, 0}, {"int", 3, 0}};
  run.fifos = {{"pixel_buffer", 20, 2}};
  run.maxRaysInFlight = 3;
  run.lastWriteCycle = 151;
  return run;
}

}  // namespace

TEST_CASE("ray pipe statistics: totals and rates of a hand-made frame", "[raypipe_statistics]") {
  const RaypipeStatistics s = RaypipeStatistics::of(handRun(130), RaypipeConfig{});
  CHECK(s.rays == 3);
  CHECK(s.totalCycles == 151);
  CHECK(s.hits == 1);
  CHECK(s.boxMisses == 1);
  CHECK(s.nodes == 5);
  CHECK(s.triangleTests == 3);
  CHECK(s.restarts == 1);
  CHECK(s.dropped == 1);
  CHECK(s.cyclesPerRay() == Approx(151.0 / 3));
  CHECK(s.frameMilliseconds() == Approx(151.0 / 50000));  // 50 MHz: 50,000 cycles a ms
  CHECK(s.framesPerSecond() == Approx(50e6 / 151));
  CHECK(s.raysPerSecond() == Approx(3 * 50e6 / 151));
}

TEST_CASE("ray pipe statistics: utilisation of each unit's full rate and the limit",
          "[raypipe_statistics]") {
  RaypipeConfig config;
  // TRAV took a node in 130 of 151 cycles: 86 %, saturated; the PRG's 3 pixels at one every 3
  // cycles are 9 of 151.
  RaypipeStatistics s = RaypipeStatistics::of(handRun(130), config);
  CHECK(s.utilisation(s.units[0]) == Approx(9.0 / 151));
  CHECK(s.utilisation(s.units[2]) == Approx(130.0 / 151));
  CHECK(s.limit() == "trav");
  CHECK(s.limitUtilisation() == Approx(130.0 / 151));
  // 100 of 151 is below 0.8: nothing limits.
  s = RaypipeStatistics::of(handRun(100), config);
  CHECK(s.limit() == "none");
  CHECK(s.limitUtilisation() == Approx(100.0 / 151));
  // A PRG that issues one pixel every 50 cycles: 3 pixels fill 150 of the 151 cycles.
  config.latency.prgInterval = 50;
  s = RaypipeStatistics::of(handRun(100), config);
  CHECK(s.units[0].interval == 50);
  CHECK(s.limit() == "prg");
  CHECK(s.limitUtilisation() == Approx(150.0 / 151));
}

TEST_CASE("ray pipe statistics: the VGA window as the limit", "[raypipe_statistics]") {
  RaypipeConfig config;
  // TRAV at 100 of 151 (66 %): nothing saturated by its own work. The SRAM writer took its 3
  // pixels and waited 120 cycles for the VGA reader with one: 123 of 151 cycles, 81 %.
  RaypipeCycleRun run = handRun(100);
  run.units.push_back({"pixel_writer", 3, 120});
  run.writerWaits = 120;
  RaypipeStatistics s = RaypipeStatistics::of(run, config);
  CHECK(s.heldUtilisation(s.units.back()) == Approx(123.0 / 151));
  CHECK(s.limit() == "vga_window");
  CHECK(s.limitUtilisation() == Approx(123.0 / 151));
  CHECK(statisticsJson(s)["limit"] == "vga_window");
  // A writer that held a pixel in fewer cycles (90 + 3 of 151: 62 %), or a unit saturated by its
  // own work, or no waits at all (the writer's stall then is no window's) is no window bound.
  run.units.back().stall = run.writerWaits = 90;
  CHECK(RaypipeStatistics::of(run, config).limit() == "none");
  run.units.back().stall = run.writerWaits = 120;
  run.units[2].busy = 130;
  CHECK(RaypipeStatistics::of(run, config).limit() == "trav");
  run.units[2].busy = 100;
  run.writerWaits = 0;
  CHECK(RaypipeStatistics::of(run, config).limit() == "none");
}

TEST_CASE("ray pipe statistics: the JSON", "[raypipe_statistics]") {
  const nlohmann::ordered_json json =
      statisticsJson(RaypipeStatistics::of(handRun(130), RaypipeConfig{}));
  CHECK(json["total_cycles"] == 151);
  CHECK(json["misses"] == 1);
  CHECK(json["traversal"]["nodes"] == 5);
  CHECK(json["ray_ids"]["available"] == 512);
  CHECK(json["ray_ids"]["most_held"] == 3);
  CHECK(json["writer"]["last_write_cycle"] == 151);
  CHECK(json["units"][2]["unit"] == "trav");
  CHECK(json["units"][2]["utilisation"].get<double>() == Approx(130.0 / 151));
  CHECK(json["units"][1]["stall"] == 5);
  CHECK(json["fifos"][0]["fifo"] == "pixel_buffer");
  CHECK(json["fifos"][0]["peak"] == 2);
  CHECK(json["limit"] == "trav");
  CHECK(json["simulation"]["model"] == "raypipe");
}

}  // namespace rtu
