// The timed model of seed 001's ray pipe (sim/raypipe/raypipe_timed.h) against the per-cycle
// reference (reference/raypipe_cycles.h) in every cycle: on the reference's own scenes, every
// transfer of every unit (cycle, unit, ray id, pixel), every ray's result, counters and issue,
// shader and exit cycles, the frame's cycles, every unit's busy and stall cycles and every FIFO's
// peak are the same; and the results equal the golden k-d traversal.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "base/float_bits.h"
#include "kd_hand_scene.h"
#include "raypipe_scenes.h"
#include "reference/raypipe_cycles.h"
#include "reference/raypipe_vga.h"
#include "sim/raypipe/raypipe_timed.h"
#include "sim/raypipe/vga_window.h"

namespace rtu {
namespace {

using TransferKey = std::tuple<int64_t, std::string, uint32_t, uint32_t>;

std::vector<TransferKey> sortedTransfers(const RaypipeCycleRun& run) {
  std::vector<TransferKey> keys;
  for (const RaypipeTransfer& t : run.transfers)
    keys.emplace_back(t.cycle, t.unit, t.rayId, t.index);
  std::sort(keys.begin(), keys.end());
  return keys;
}

void checkSameResult(const RaypipeCycleResult& a, const RaypipeCycleResult& b) {
  CHECK(a.pixelId == b.pixelId);
  CHECK(a.hit == b.hit);
  CHECK(a.boxMiss == b.boxMiss);
  CHECK(floatBits(a.t) == floatBits(b.t));
  CHECK(floatBits(a.u) == floatBits(b.u));
  CHECK(floatBits(a.v) == floatBits(b.v));
  CHECK(a.primitive == b.primitive);
  CHECK(a.counts.nodes == b.counts.nodes);
  CHECK(a.counts.leaves == b.counts.leaves);
  CHECK(a.counts.triangleTests == b.counts.triangleTests);
  CHECK(a.counts.restarts == b.counts.restarts);
  CHECK(a.counts.boxMisses == b.counts.boxMisses);
  CHECK(a.counts.pushes == b.counts.pushes);
  CHECK(a.counts.dropped == b.counts.dropped);
  CHECK(a.issueCycle == b.issueCycle);
  CHECK(a.shaderInCycle == b.shaderInCycle);
  CHECK(a.exitCycle == b.exitCycle);
  CHECK(a.rayId == b.rayId);
}

// The timed model's run equals the reference's in every recorded field and every transfer.
RaypipeCycleRun checkSameCycles(const KdImage& image, const std::vector<RaypipeCycleRay>& rays,
                                const RaypipeConfig& config, RaypipeCycleOptions options = {}) {
  options.recordTransfers = true;
  const RaypipeCycleRun ref = runRaypipeCycles(config, image, rays, options);
  const RaypipeCycleRun timed = runRaypipeTimed(config, image, rays, options);
  REQUIRE(timed.results.size() == ref.results.size());
  for (size_t i = 0; i < rays.size(); ++i) {
    INFO("ray " << i);
    checkSameResult(timed.results[i], ref.results[i]);
  }
  CHECK(timed.lastExitCycle == ref.lastExitCycle);
  CHECK(timed.frameCycles == ref.frameCycles);
  CHECK(timed.lastWriteCycle == ref.lastWriteCycle);
  CHECK(timed.writerWaits == ref.writerWaits);
  CHECK(timed.maxRaysInFlight == ref.maxRaysInFlight);
  CHECK(timed.staleListHits == ref.staleListHits);
  REQUIRE(timed.units.size() == ref.units.size());
  for (size_t i = 0; i < ref.units.size(); ++i) {
    INFO(ref.units[i].unit);
    CHECK(timed.units[i].unit == ref.units[i].unit);
    CHECK(timed.units[i].busy == ref.units[i].busy);
    CHECK(timed.units[i].stall == ref.units[i].stall);
  }
  REQUIRE(timed.fifos.size() == ref.fifos.size());
  for (size_t i = 0; i < ref.fifos.size(); ++i) {
    INFO(ref.fifos[i].fifo);
    CHECK(timed.fifos[i].fifo == ref.fifos[i].fifo);
    CHECK(timed.fifos[i].depth == ref.fifos[i].depth);
    CHECK(timed.fifos[i].peak == ref.fifos[i].peak);
  }
  CHECK(timed.transfers.size() == ref.transfers.size());
  CHECK(sortedTransfers(timed) == sortedTransfers(ref));
  REQUIRE(timed.caches.size() == ref.caches.size());
  for (size_t i = 0; i < ref.caches.size(); ++i) {
    INFO(ref.caches[i].cache);
    CHECK(timed.caches[i].cache == ref.caches[i].cache);
    CHECK(timed.caches[i].hits == ref.caches[i].hits);
    CHECK(timed.caches[i].misses == ref.caches[i].misses);
    CHECK(timed.caches[i].fills == ref.caches[i].fills);
    CHECK(timed.caches[i].reissues == ref.caches[i].reissues);
    CHECK(timed.caches[i].stalls == ref.caches[i].stalls);
  }
  CHECK(timed.dram.reads == ref.dram.reads);
  CHECK(timed.dram.bytes == ref.dram.bytes);
  CHECK(timed.dram.busyCycles == ref.dram.busyCycles);
  return timed;
}

// Every ray's result equals the golden k-d traversal's (hit, triangle, t, u, v and counters).
void checkGolden(const KdImage& image, const std::vector<RaypipeCycleRay>& rays,
                 const RaypipeConfig& config, const RaypipeCycleRun& run) {
  KdTraversalConfig c;
  c.stackDepth = config.shortStackDepth;
  c.division = config.division;
  c.tMaxClamp = config.tMaxClamp;
  const WordMemory memory = image.memory();
  for (size_t i = 0; i < rays.size(); ++i) {
    KdTraversal g(c);
    g.start(KdJob{rays[i].ray, sectionsOfImage(image)});
    while (g.busy()) g.step([&memory](uint32_t a) { return memory.read(a); });
    const RaypipeCycleResult& r = run.results[i];
    INFO("ray " << i);
    CHECK(r.hit == g.hit());
    CHECK(r.primitive == (g.hit() ? g.primitive() : 0u));
    CHECK(floatBits(r.t) == floatBits(g.hit() ? g.t() : 0.0f));
    CHECK(r.counts.nodes == g.counts().nodes);
    CHECK(r.counts.restarts == g.counts().restarts);
  }
}

}  // namespace

TEST_CASE("raypipe timed model: the reference's cycles on a few triangles", "[raypipe_timed]") {
  const KdImage image = builtImage(fewTriangles());
  const std::vector<RaypipeCycleRay> rays = mixedRays(image, 300, 1);
  RaypipeConfig config;
  for (int depth : {4, 2, 1}) {
    config.shortStackDepth = depth;
    checkGolden(image, rays, config, checkSameCycles(image, rays, config));
  }
}

TEST_CASE("raypipe timed model: the reference's cycles on a sphere-like mesh", "[raypipe_timed]") {
  const KdImage image = builtImage(sphereCorners({0.5, 0.25, 2}, 6, 10));
  const std::vector<RaypipeCycleRay> rays = mixedRays(image, 400, 2);
  RaypipeConfig config;
  for (int depth : {1, 2}) {
    config.shortStackDepth = depth;
    checkGolden(image, rays, config, checkSameCycles(image, rays, config));
  }
  config.shortStackDepth = 4;
  config.tMaxClamp = KdTMaxClamp::Intended;
  checkGolden(image, rays, config, checkSameCycles(image, rays, config));
}

TEST_CASE("raypipe timed model: the reference's cycles with small FIFOs", "[raypipe_timed]") {
  const KdImage image = builtImage(sphereCorners({0.5, 0.25, 2}, 6, 10));
  const std::vector<RaypipeCycleRay> rays = mixedRays(image, 400, 4);
  RaypipeConfig config;
  config.fifo.travLeaf = 1;
  config.fifo.pixelBuffer = 1;
  config.fifo.prg = 14;
  config.fifo.sint = 6;
  config.fifo.travMath = 14;
  config.fifo.intList = config.fifo.intLarb = 45;
  config.fifo.intShader = 1;
  config.shortStackDepth = 2;
  const RaypipeCycleRun run = checkSameCycles(image, rays, config);
  int64_t stalls = 0;
  for (const RaypipeUnitActivity& a : run.units) stalls += a.stall;
  CHECK(stalls > 1000);
}

TEST_CASE("raypipe timed model: the reference's cycles on the hand scene", "[raypipe_timed]") {
  const KdImage image = layOutKd(handKdScene());
  std::vector<RaypipeCycleRay> rays;
  for (int i = 0; i < 40; ++i)
    rays.push_back(
        RaypipeCycleRay{KdRay{{-1.0f + 0.1f * i, 0.05f * i, 0.04f * i}, {1, 0.01f, 0.02f}, false},
                        static_cast<uint32_t>(i)});
  RaypipeConfig config;
  config.shortStackDepth = 1;
  checkSameCycles(image, rays, config);
  // nine rays meeting once at tarb (the hand count of docs/raypipe.md: the last leaves at 216)
  const KdRay a{{0.5f, 0.25f, 0.25f}, {1, 0, 0}, false};
  std::vector<RaypipeCycleRay> nine;
  for (uint32_t k = 0; k < 9; ++k) nine.push_back(RaypipeCycleRay{a, k});
  CHECK(checkSameCycles(image, nine, RaypipeConfig{}).results[8].exitCycle == 216);
}

TEST_CASE("raypipe timed model: the reference's cycles on one triangle", "[raypipe_timed]") {
  const KdImage image = oneTriangle();
  const KdRay hit = downZ(0.5f, 0.5f), miss = downZ(1.5f, 1.5f);
  const KdRay boxMiss{{5, 5, 0}, {0, 0, 1}, false};
  RaypipeConfig config;
  CHECK(checkSameCycles(image, {{hit, 7}}, config).results[0].exitCycle == 143);
  CHECK(checkSameCycles(image, {{boxMiss, 0}}, config).results[0].exitCycle == 67);
  checkSameCycles(image, {{hit, 0}, {boxMiss, 1}, {miss, 2}, {hit, 3}}, config);
  RaypipeCycleOptions atReset;
  atReset.cyclesSinceReset = 0;
  CHECK(checkSameCycles(image, {{boxMiss, 0}}, config, atReset).results[0].exitCycle == 515);
  // the set-associative caches' hand count (test_raypipe_cycles.cpp): three cold misses
  config.cache = RaypipeCacheKind::SetAssociative;
  const RaypipeCycleRun cached = checkSameCycles(image, {{hit, 0}, {hit, 1}}, config);
  CHECK(cached.results[0].exitCycle == 213);
  CHECK(cached.results[1].exitCycle == 214);
}

TEST_CASE("raypipe timed model: the reference's cycles on PRG rays at 20x15 and 40x30",
          "[raypipe_timed]") {
  const KdImage image = frameScene();
  RaypipeConfig config;
  checkSameCycles(image, prgRays(0), config);
  for (int depth : {4, 2}) {
    config.shortStackDepth = depth;
    checkGolden(image, prgRays(1), config, checkSameCycles(image, prgRays(1), config));
  }
}

TEST_CASE("raypipe timed model: the reference's cycles with 4 rays in flight", "[raypipe_timed]") {
  const KdImage image = builtImage(sphereCorners({0, 0, 3}, 5, 8));
  const std::vector<RaypipeCycleRay> rays = mixedRays(image, 500, 9);
  RaypipeConfig config;
  config.raysInFlight = 4;
  CHECK(checkSameCycles(image, rays, config).maxRaysInFlight == 4);
  config.raysInFlight = 1;
  checkSameCycles(image, mixedRays(builtImage(fewTriangles()), 12, 5), config);
}

TEST_CASE("raypipe timed model: the reference's cycles with other latencies and a frame at reset",
          "[raypipe_timed]") {
  const KdImage image = builtImage(sphereCorners({0.5, 0.25, 2}, 6, 10));
  const std::vector<RaypipeCycleRay> rays = mixedRays(image, 300, 6);
  RaypipeConfig config;
  config.latency.prg = 20;
  config.latency.sint = 9;
  config.latency.travMath = 7;
  config.latency.intersection = 20;
  config.latency.memoryRead = 1;
  config.latency.prgInterval = 2;
  config.latency.sintInterval = 4;
  config.division = Division::TowardZero;
  checkSameCycles(image, rays, config);
  RaypipeCycleOptions atReset;
  atReset.cyclesSinceReset = 100;
  checkSameCycles(image, rays, RaypipeConfig{}, atReset);
}

TEST_CASE("raypipe timed model: refused settings", "[raypipe_timed]") {
  const KdImage image = oneTriangle();
  const std::vector<RaypipeCycleRay> rays = {{downZ(0.5f, 0.5f), 0}};
  RaypipeConfig three;
  three.traversalUnits = 3;
  CHECK_THROWS_AS(runRaypipeTimed(three, image, rays), std::invalid_argument);
  RaypipeCycleOptions vga;
  vga.writer.vgaReadWindow = true;
  vga.writer.vgaPhase = -1;
  CHECK_THROWS_AS(runRaypipeTimed(RaypipeConfig{}, image, rays, vga), std::invalid_argument);
}

// The closed form of the VGA reader's window (sim/raypipe/vga_window.h) against the reference's
// stepped counters (reference/raypipe_vga.h) over a screen and a half, from two phases.
TEST_CASE("raypipe timed model: the VGA window equals the reference's counters",
          "[raypipe_timed]") {
  for (const int64_t phase : {int64_t{0}, int64_t{49885}}) {
    raypipe_ref::VgaReader stepped;
    for (int64_t i = 0; i < phase; ++i) stepped.tick();
    const raypipe_timed::VgaWindow window(phase);
    int64_t differ = 0;
    for (int64_t n = 0; n < 3 * raypipe_timed::VgaWindow::kScreen / 2; ++n) {
      differ += stepped.reading() != window.reading(n);
      stepped.tick();
    }
    CHECK(differ == 0);
  }
}

// With the VGA reader's window: the writer waits, and with a small pixel buffer the buffer fills
// and the shader stalls, in the same cycles as the reference.
TEST_CASE("raypipe timed model: equivalence with the VGA reader's window", "[raypipe_timed]") {
  const KdImage image = frameScene();
  const std::vector<RaypipeCycleRay> rays = prgRays(1);
  RaypipeCycleOptions options;
  options.writer.vgaReadWindow = true;
  for (const int64_t phase : {int64_t{49886}, int64_t{5208}, int64_t{833599}}) {
    INFO("phase " << phase);
    options.writer.vgaPhase = phase;
    const RaypipeCycleRun run = checkSameCycles(image, rays, RaypipeConfig{}, options);
    RaypipeConfig small;
    small.fifo.pixelBuffer = 1;
    const RaypipeCycleRun filled = checkSameCycles(image, rays, small, options);
    if (phase == 49886) {
      CHECK(run.writerWaits > 0);
      CHECK(filled.writerWaits > 0);
    }
  }
}

}  // namespace rtu

namespace rtu {
namespace {

int64_t fifoPeak(const RaypipeCycleRun& run, const std::string& name) {
  for (const RaypipeFifoPeak& f : run.fifos)
    if (f.fifo == name) return f.peak;
  FAIL("no FIFO " << name);
  return -1;
}

}  // namespace

// Two traversal units (raypipe_2trav.sv): tarb is general_arbitor 5 -> 2 ([0] pop, [1] restart,
// [2] trav0, [3] trav1, [4] SINT), output o taking the first valid input from the shared pointer
// that no earlier output took. The nine rays of the hand count above (one unit: ray 8 waits a
// cycle at 87 and leaves at 216): tarb took one item in each of the 8 cycles 63 ... 84, so at 87
// its pointer is 3; output 0 scans 3, 4 and takes SINT's ray 8, output 1 goes on 0, 1, 2 and takes
// ray 0's node 1 from TRAV 0, which so reaches TRAV 1. Neither waits: ray 8 leaves at 87 + 128 =
// 215. At 111 (16 cycles with a grant: pointer 1) ray 8's node 1 from TRAV 0 (input 2) and ray
// 0's leaf from TRAV 1 (input 3) meet: output 0 takes input 2, output 1 input 3, again no wait. No
// other offers meet, at tarb, larb or the list unit's leaf_max: every ray leaves at 191 + 3k, and
// only ray 0's node 1 and leaf went through unit 1 (its tcache FIFO held one node at a time).
TEST_CASE("raypipe timed model: two traversal units, hand-counted", "[raypipe_timed]") {
  const KdImage image = layOutKd(handKdScene());
  const KdRay a{{0.5f, 0.25f, 0.25f}, {1, 0, 0}, false};
  std::vector<RaypipeCycleRay> nine;
  for (uint32_t k = 0; k < 9; ++k) nine.push_back(RaypipeCycleRay{a, k});
  RaypipeConfig two;
  two.traversalUnits = 2;
  RaypipeCycleOptions options;
  options.recordTransfers = true;
  const RaypipeCycleRun run = checkSameCycles(image, nine, two, options);
  for (uint32_t k = 0; k < 9; ++k) CHECK(run.results[k].exitCycle == 191 + 3 * k);
  CHECK(fifoPeak(run, "tarb_1") == 1);
  CHECK(fifoPeak(run, "tcache_1") == 1);
  CHECK(fifoPeak(run, "trav_leaf_1") == 1);
  int64_t tcacheTakes = 0;  // ray 0's three nodes and ray k's: 27, over both units
  for (const RaypipeTransfer& t : run.transfers) tcacheTakes += t.unit == std::string("tcache");
  CHECK(tcacheTakes == 27);
  // One unit: the reference's cycles, ray 8 a cycle late.
  CHECK(runRaypipeTimed(RaypipeConfig{}, image, nine).results[8].exitCycle == 216);
}

// The set-associative caches (timed_cache.h, reference/raypipe_cache.h): the RTL's sizes (cold
// misses only), small caches (conflicts and evictions: a few lines per way) and a slow DRAM (the
// reissue FIFO fills and stalls the caches' inputs), on the reference's scenes and PRG frames.
namespace {

RaypipeConfig setAssociative(int tcache, int lcache, int icache) {
  RaypipeConfig config;
  config.cache = RaypipeCacheKind::SetAssociative;
  config.caches.tcacheLines = tcache;
  config.caches.lcacheLines = lcache;
  config.caches.icacheLines = icache;
  return config;
}

int64_t total(const RaypipeCycleRun& run, int64_t RaypipeCacheCounts::*field) {
  int64_t sum = 0;
  for (const RaypipeCacheCounts& c : run.caches) sum += c.*field;
  return sum;
}

}  // namespace

TEST_CASE("raypipe timed model: the reference's cycles with the set-associative caches",
          "[raypipe_timed]") {
  const KdImage sphere = builtImage(sphereCorners({0.5, 0.25, 2}, 6, 10));
  const std::vector<RaypipeCycleRay> rays = mixedRays(sphere, 400, 2);
  RaypipeConfig config = setAssociative(512, 1024, 1024);
  RaypipeCycleRun run = checkSameCycles(sphere, rays, config);
  checkGolden(sphere, rays, config, run);
  CHECK(total(run, &RaypipeCacheCounts::fills) == run.dram.reads);
  config = setAssociative(2, 1, 4);
  for (int depth : {1, 4}) {
    config.shortStackDepth = depth;
    run = checkSameCycles(sphere, rays, config);
    checkGolden(sphere, rays, config, run);
  }
  CHECK(total(run, &RaypipeCacheCounts::fills) > 100);  // lines evicted and read again
  config.caches.dramLatency = 60;
  config.caches.dramBytesPerCycle = 1;
  run = checkSameCycles(sphere, rays, config);
  checkGolden(sphere, rays, config, run);
  CHECK(total(run, &RaypipeCacheCounts::stalls) > 1000);
  const KdImage frame = frameScene();
  for (int level : {0, 1}) {
    config = setAssociative(4, 2, 8);
    run = checkSameCycles(frame, prgRays(level), config);
    checkGolden(frame, prgRays(level), config, run);
  }
  RaypipeCycleOptions atReset;  // the way choice's and the arbiter's phase
  atReset.cyclesSinceReset = 101;
  checkSameCycles(frame, prgRays(0), config, atReset);
  config.latency.memoryRead = 3;  // a reissue FIFO sized for a longer read
  checkGolden(sphere, rays, config, checkSameCycles(sphere, rays, config));
}

// With two units every result equals the golden traversal's (and the one-unit run's), on scenes
// where the units' outputs meet at tarb, larb, the shortstack's ports and the list unit's leaf_max
// RAM, cycle for cycle the per-cycle reference's; and a traversal-bound frame takes fewer cycles.
TEST_CASE("raypipe timed model: two traversal units give the golden results", "[raypipe_timed]") {
  RaypipeConfig one, two;
  two.traversalUnits = 2;
  const KdImage sphere = builtImage(sphereCorners({0.5, 0.25, 2}, 6, 10));
  const std::vector<RaypipeCycleRay> rays = mixedRays(sphere, 400, 2);
  for (int depth : {1, 4}) {
    one.shortStackDepth = two.shortStackDepth = depth;
    const RaypipeCycleRun run = checkSameCycles(sphere, rays, two);
    checkGolden(sphere, rays, two, run);
    const RaypipeCycleRun single = runRaypipeTimed(one, sphere, rays);
    for (size_t i = 0; i < rays.size(); ++i) {
      INFO("ray " << i);
      CHECK(run.results[i].primitive == single.results[i].primitive);
      CHECK(floatBits(run.results[i].u) == floatBits(single.results[i].u));
      CHECK(floatBits(run.results[i].v) == floatBits(single.results[i].v));
      CHECK(run.results[i].counts.pushes == single.results[i].counts.pushes);
    }
    CHECK(run.frameCycles < single.frameCycles);
  }
  const KdImage frame = frameScene();
  const RaypipeCycleRun small = checkSameCycles(frame, prgRays(1), two);
  checkGolden(frame, prgRays(1), two, small);
  CHECK(fifoPeak(small, "tcache_1") > 0);
  RaypipeConfig shallow = two;  // small FIFOs: every stall path of the second unit
  shallow.fifo.travLeaf = 1;
  shallow.fifo.travMath = 14;
  shallow.fifo.pixelBuffer = 1;
  shallow.fifo.intList = shallow.fifo.intLarb = 45;
  checkGolden(sphere, rays, shallow, checkSameCycles(sphere, rays, shallow));
  RaypipeConfig cached = setAssociative(2, 1, 4);  // four caches behind the arbiter
  cached.traversalUnits = 2;
  const RaypipeCycleRun withCaches = checkSameCycles(sphere, rays, cached);
  checkGolden(sphere, rays, cached, withCaches);
  REQUIRE(withCaches.caches.size() == 4);
  CHECK(withCaches.caches[1].cache == "tcache_1");
  CHECK(withCaches.caches[1].fills > 0);
}

}  // namespace rtu
