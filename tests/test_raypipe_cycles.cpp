// The per-cycle reference of seed 001's ray pipe (reference/raypipe_cycles.h): per-ray results
// bit-exact with the golden k-d traversal on small pbrt-built scenes, exit cycles counted by hand
// from the timing rules (docs/raypipe.md, "Timing rules (the per-cycle reference)"), and the pipe's
// invariants.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "kd_hand_scene.h"
#include "kinds/kd/kd_kind.h"
#include "kinds/kd/pbrt_kd_builder.h"
#include "raypipe_scenes.h"
#include "reference/raypipe_cycles.h"
#include "reference/raypipe_vga.h"

namespace rtu {
namespace {

KdTraversal golden(const KdImage& image, const KdRay& ray, const RaypipeConfig& config) {
  KdTraversalConfig c;
  c.stackDepth = config.shortStackDepth;
  c.division = config.division;
  c.tMaxClamp = config.tMaxClamp;
  KdTraversal traversal(c);
  traversal.start(KdJob{ray, sectionsOfImage(image)});
  const WordMemory memory = image.memory();
  while (traversal.busy()) traversal.step([&memory](uint32_t a) { return memory.read(a); });
  return traversal;
}

struct Coverage {
  int hits = 0, boxMisses = 0, restarts = 0, dropped = 0, pushes = 0;
};

// Every ray's result and counters equal the golden traversal's, bit for bit.
Coverage checkAgainstGolden(const KdImage& image, const std::vector<RaypipeCycleRay>& rays,
                            const RaypipeConfig& config) {
  const RaypipeCycleRun run = runRaypipeCycles(config, image, rays);
  REQUIRE(run.results.size() == rays.size());
  Coverage coverage;
  for (size_t i = 0; i < rays.size(); ++i) {
    const KdTraversal g = golden(image, rays[i].ray, config);
    const RaypipeCycleResult& r = run.results[i];
    INFO("ray " << i);
    CHECK(r.pixelId == rays[i].pixelId);
    CHECK(r.hit == g.hit());
    const KdRayCounts gc = g.counts();
    CHECK(r.boxMiss == (gc.boxMisses == 1));
    if (g.hit()) {
      CHECK(floatBits(r.t) == floatBits(g.t()));
      CHECK(floatBits(r.u) == floatBits(g.u()));
      CHECK(floatBits(r.v) == floatBits(g.v()));
      CHECK(r.primitive == g.primitive());
    }
    CHECK(r.counts.nodes == gc.nodes);
    CHECK(r.counts.leaves == gc.leaves);
    CHECK(r.counts.triangleTests == gc.triangleTests);
    CHECK(r.counts.restarts == gc.restarts);
    CHECK(r.counts.boxMisses == gc.boxMisses);
    CHECK(r.counts.pushes == gc.pushes);
    CHECK(r.counts.dropped == gc.dropped);
    CHECK(r.exitCycle > r.shaderInCycle);
    CHECK(r.shaderInCycle > r.issueCycle);
    coverage.hits += g.hit() ? 1 : 0;
    coverage.boxMisses += static_cast<int>(gc.boxMisses);
    coverage.restarts += static_cast<int>(gc.restarts);
    coverage.dropped += static_cast<int>(gc.dropped);
    coverage.pushes += static_cast<int>(gc.pushes);
  }
  for (const RaypipeFifoPeak& f : run.fifos) {
    INFO(f.fifo);
    CHECK(f.peak <= f.depth);
  }
  CHECK(run.maxRaysInFlight <= config.raysInFlight);
  return coverage;
}

}  // namespace

TEST_CASE("raypipe reference: results equal the golden traversal on small scenes",
          "[raypipe_cycles]") {
  RaypipeConfig config;
  SECTION("a few triangles with stack depths 4 then 2 then 1") {
    const KdImage image = builtImage(fewTriangles());
    const std::vector<RaypipeCycleRay> rays = mixedRays(image, 300, 1);
    for (int depth : {4, 2, 1}) {
      config.shortStackDepth = depth;
      const Coverage c = checkAgainstGolden(image, rays, config);
      CHECK(c.hits > 20);
      CHECK(c.boxMisses > 10);
      CHECK(c.pushes > 0);
    }
  }
  SECTION("a sphere-like mesh with overflows and restarts") {
    const KdImage image = builtImage(sphereCorners({0.5, 0.25, 2}, 6, 10));
    const std::vector<RaypipeCycleRay> rays = mixedRays(image, 400, 2);
    config.shortStackDepth = 1;
    const Coverage one = checkAgainstGolden(image, rays, config);
    CHECK(one.restarts > 0);
    CHECK(one.dropped > 0);
    config.shortStackDepth = 2;
    CHECK(checkAgainstGolden(image, rays, config).dropped > 0);
    config.shortStackDepth = 4;
    config.tMaxClamp = KdTMaxClamp::Intended;
    const Coverage four = checkAgainstGolden(image, rays, config);
    CHECK(four.hits > 50);
  }
  SECTION("small FIFOs: every stall path taken") {
    // The FIFOs behind a pipe_valid_stall kept deep enough for the pipe's items in flight (the
    // credit rule can overfill shallower ones: docs/raypipe.md), the others at 1.
    const KdImage image = builtImage(sphereCorners({0.5, 0.25, 2}, 6, 10));
    const std::vector<RaypipeCycleRay> rays = mixedRays(image, 400, 4);
    config.fifo.travLeaf = 1;
    config.fifo.pixelBuffer = 1;
    config.fifo.prg = 14;  // the PRG's pipe holds at most 41 / 3 rays
    config.fifo.sint = 6;  // SINT's at most 18 / 3
    config.fifo.travMath = 14;
    config.fifo.intList = config.fifo.intLarb = 45;
    config.fifo.intShader = 1;  // INT's credit: the least free space
    config.shortStackDepth = 2;
    const RaypipeCycleRun run = runRaypipeCycles(config, image, rays);
    int64_t stalls = 0;
    for (const RaypipeUnitActivity& a : run.units) stalls += a.stall;
    CHECK(stalls > 1000);
    checkAgainstGolden(image, rays, config);
  }
  SECTION("the hand scene") {
    const KdImage image = layOutKd(handKdScene());
    std::vector<RaypipeCycleRay> rays;
    for (int i = 0; i < 40; ++i)
      rays.push_back(
          RaypipeCycleRay{KdRay{{-1.0f + 0.1f * i, 0.05f * i, 0.04f * i}, {1, 0.01f, 0.02f}, false},
                          static_cast<uint32_t>(i)});
    config.shortStackDepth = 1;
    checkAgainstGolden(image, rays, config);
  }
}

// Hand-counted exit cycles on one triangle (the root is a leaf), from the rules of docs/raypipe.md:
//   PRG accepts on v0 (cycle % 3 == 0): cycle 0; its pipe (41) writes the 16-deep BRAM FIFO at
//     41, shown 2 cycles after a write: 43
//   the shader gives the ray an id and SINT accepts on v2 (cycle % 3 == 2): 44
//   SINT's pipe (18) writes its register FIFO at 62, at its head at 63
//   tarb's VS_buf passes it on (no stall registered), the arbiter writes its BRAM FIFO at 63,
//     shown at 65; tcache's pipe (2) at 67, its FIFO's head at 68
//   TRAV: a leaf into the leaf FIFO at 68, its head at 69; the larb register at 70
//   larb writes its BRAM FIFO at 70, shown at 72; lcache 72 + 2 -> head 75; icache 75 + 2 -> 78;
//     raystore #1 78 + 2 -> 81
//   INT accepts at 81, its pipe (45) writes the BRAM list FIFO at 126, shown at 128
//   the list unit's VS pipe (4) from 128 writes the last FIFO at 132, its head at 133
//   a hit: hit pipe (2) 133 -> hit FIFO's head 136; raystore #2 136 + 2 -> 139
//     a miss instead: the to-shortstack register at 134, the restart read FIFO's head at 135,
//     the restart pipe (3) writes the miss FIFO at 138, its head at 139
//   the shader's arbiter writes its register FIFO at 139, head at 140; its VS pipe (2) writes the
//     ray-data FIFO at 142; its head leaves into the pixel buffer at 143
//   a box miss: SINT's shader FIFO at 63, the arbiter's FIFO head at 64, the VS pipe to 66, out
//     at 67
TEST_CASE("raypipe reference: hand-counted cycles on one triangle", "[raypipe_cycles]") {
  const KdImage image = oneTriangle();
  RaypipeConfig config;
  const KdRay hit = downZ(0.5f, 0.5f), miss = downZ(1.5f, 1.5f);
  const KdRay boxMiss{{5, 5, 0}, {0, 0, 1}, false};
  SECTION("one ray") {
    RaypipeCycleRun run = runRaypipeCycles(config, image, {{hit, 7}});
    REQUIRE(run.results.size() == 1);
    CHECK(run.results[0].hit);
    CHECK(run.results[0].issueCycle == 0);
    CHECK(run.results[0].shaderInCycle == 44);
    CHECK(run.results[0].exitCycle == 143);
    CHECK(run.lastExitCycle == 143);
    CHECK(run.frameCycles == 144);
    CHECK(run.lastWriteCycle == 144);  // the pixel buffer's head one cycle after the write
    // The same ray's transfers, unit by unit, at the cycles counted above.
    RaypipeCycleOptions options;
    options.recordTransfers = true;
    run = runRaypipeCycles(config, image, {{hit, 7}}, options);
    std::vector<std::pair<std::string, int64_t>> seen;
    for (const RaypipeTransfer& t : run.transfers) seen.emplace_back(t.unit, t.cycle);
    const std::vector<std::pair<std::string, int64_t>> expected = {
        {"prg", 0},           {"sint", 44},  {"tarb", 63},        {"tcache", 65},
        {"trav", 68},         {"larb", 70},  {"lcache", 72},      {"icache", 75},
        {"int", 81},          {"list", 128}, {"shader_arb", 139}, {"shader_return", 140},
        {"pixel_writer", 144}};
    CHECK(seen == expected);
    run = runRaypipeCycles(config, image, {{miss, 0}});
    CHECK_FALSE(run.results[0].hit);
    CHECK(run.results[0].exitCycle == 143);
    run = runRaypipeCycles(config, image, {{boxMiss, 0}});
    CHECK(run.results[0].boxMiss);
    CHECK(run.results[0].exitCycle == 67);
    // A frame started at reset (R1's shader fills its ray ids over 512 cycles, id 0 written in
    // cycle 0, shown at 2, and blocks its arbiter's output until cycle 512): the box miss enters
    // SINT at 44 as before, waits at the arbiter's output from 64 to 512, the VS pipe to 514,
    // the ray-data FIFO's head at 515: out at 515.
    RaypipeCycleOptions atReset;
    atReset.cyclesSinceReset = 0;
    run = runRaypipeCycles(config, image, {{boxMiss, 0}}, atReset);
    CHECK(run.results[0].shaderInCycle == 44);
    CHECK(run.results[0].exitCycle == 515);
  }
  SECTION("a handful of rays") {
    // The PRG accepts one ray every 3 cycles (0, 3, 6, 9); each then keeps its distance of 3
    // cycles through every unit, so nothing waits: each leaves at its issue cycle plus its
    // single-ray latency (143 for a leaf, 67 for a box miss).
    const RaypipeCycleRun run =
        runRaypipeCycles(config, image, {{hit, 0}, {boxMiss, 1}, {miss, 2}, {hit, 3}});
    CHECK(run.results[0].exitCycle == 143);
    CHECK(run.results[1].exitCycle == 3 + 67);
    CHECK(run.results[2].exitCycle == 6 + 143);
    CHECK(run.results[3].exitCycle == 9 + 143);
    CHECK(run.lastExitCycle == 152);
  }
}

// The set-associative caches (docs/raypipe.md, "The set-associative caches"; DRAM latency 8, 4
// bytes a cycle), on one triangle, counted by hand from the rules:
//   tcache: the root enters at 65 (as above), a cold miss; out at 67 into the reissue FIFO, its
//     line into the request FIFO, shown at 68; the miss handler asks from 69. The arbiter, idle
//     since cycle 0, looks at port t mod 4 in cycle t: tcache's port 1 at 69, granted; doneRead
//     at 69 + 8 + 48 / 4 = 89. The root goes in again at 89 (its line written: a hit), out at 91,
//     the hit FIFO's head at 92: TRAV at 92 (68 before: 24 later).
//   lcache: in at 72 + 24 = 96, a miss, out at 98, asks from 100; the arbiter is idle from 90 with
//     its pointer at port 2, at port (2 + t - 90) mod 4 in cycle t: port 2 at 102; doneRead at
//     102 + 8 + 32 / 4 = 118; in again at 118, out at 120, head at 121: icache in at 121.
//   icache: a miss, out at 123, asks from 125; the arbiter is idle from 119 at port 3: port 0 at
//     128; doneRead at 128 + 8 + 36 / 4 = 145; in again at 145, out at 147, head at 148: raystore
//     #1 at 148, 70 after the block RAMs' 78, so the ray leaves at 143 + 70 = 213.
//   a second ray 3 cycles behind finds each line asked for already (in the request FIFO): it waits
//     behind the first in the reissue FIFO, goes in the cycle after it (a hit) and keeps one cycle
//     behind it to the end: 214.
TEST_CASE("raypipe reference: hand-counted cycles with the set-associative caches",
          "[raypipe_cycles]") {
  const KdImage image = oneTriangle();
  RaypipeConfig config;
  config.cache = RaypipeCacheKind::SetAssociative;
  config.caches.dramLatency = 8;
  config.caches.dramBytesPerCycle = 4;
  const KdRay hit = downZ(0.5f, 0.5f);
  RaypipeCycleOptions options;
  options.recordTransfers = true;
  RaypipeCycleRun run = runRaypipeCycles(config, image, {{hit, 7}}, options);
  CHECK(run.results[0].hit);
  CHECK(run.results[0].exitCycle == 213);
  std::vector<std::pair<std::string, int64_t>> seen;
  for (const RaypipeTransfer& t : run.transfers) seen.emplace_back(t.unit, t.cycle);
  const std::vector<std::pair<std::string, int64_t>> expected = {
      {"prg", 0},           {"sint", 44},  {"tarb", 63},        {"tcache", 65},
      {"trav", 92},         {"larb", 94},  {"lcache", 96},      {"icache", 121},
      {"int", 151},         {"list", 198}, {"shader_arb", 209}, {"shader_return", 210},
      {"pixel_writer", 214}};
  CHECK(seen == expected);
  REQUIRE(run.caches.size() == 3);
  for (const RaypipeCacheCounts& c : run.caches) {
    INFO(c.cache);
    CHECK(c.misses == 1);
    CHECK(c.hits == 1);  // the reissue with its line
    CHECK(c.fills == 1);
  }
  CHECK(run.dram.reads == 3);
  CHECK(run.dram.bytes == 48 + 32 + 36);
  CHECK(run.dram.busyCycles == 12 + 8 + 9);
  run = runRaypipeCycles(config, image, {{hit, 0}, {hit, 1}});
  CHECK(run.results[0].exitCycle == 213);
  CHECK(run.results[1].exitCycle == 214);
  for (const RaypipeCacheCounts& c : run.caches) {
    INFO(c.cache);
    CHECK(c.misses == 2);
    CHECK(c.hits == 2);
    CHECK(c.fills == 1);
    CHECK(c.reissues == 2);
  }
  CHECK(run.dram.reads == 3);
}

// Hand-counted exit cycles on the hand scene (kd_hand_scene.h: root split x = 4 -> node 1 split
// x = 2 -> leaves 2 [T0], 3 [T1, T3], 4 [T2]), one ray along +x from x = 0.5, from the rules:
//   the root reaches TRAV at 68, as the leaf above. An interior node at TRAV in cycle T: raystore
//     #0 (2) -> its FIFO's head at T + 3; the math pipe (14) -> the 15-deep FIFO's head at T + 18,
//     decided; the tarb register at T + 19, tarb's BRAM FIFO written then, shown at T + 21;
//     tcache (2) -> head at T + 24: the next node at TRAV. So node 1 at 92, leaf 2 at 116.
//   a leaf at TRAV in cycle L leaves the shader at L + 75 on a hit (68 -> 143 above); the last
//     FIFO's head is at L + 65 (68 -> 133)
//   (a) y = z = 0.25 hits T0 in leaf 2: 116 + 75 = 191
//   (b) y = z = 0.9 misses T0 (y + z >= 1): last FIFO head 181; the miss register at 182; the
//     stack read FIFO's head 183, read, pipe (2) -> the stack FIFO's head at 186; tarb's FIFO
//     written 186, shown 188; tcache -> leaf 3 at TRAV at 191. Leaf 3's two triangles: larb
//     register 193, shown 195, lcache 198, icache 201, raystore #1 204: T1 into INT at 204, out at
//     249 into the larb FIFO (BRAM), shown 251; larb's FIFO written 251, shown 253; lcache 256,
//     icache 259, raystore #1 262: T3 into INT at 262, out 307 into the list FIFO, shown 309; list
//     pipe (4) -> last FIFO head 314, a miss: register 315, stack read FIFO head 316, the stack
//     FIFO's head 319, tarb shown 321, leaf 4 at TRAV at 324: T2 hits (y + z < 2): 324 + 75 = 399
//   (c) as (b) with a stack of 1: the push of node 3 overwrote node 4, so leaf 3's miss finds the
//     stack empty: the restart read FIFO's head at 316, the restart pipe (3) -> the restart FIFO's
//     head at 320, tarb shown 322, the root (the restart node) at TRAV at 325, only high over
//     [3.5, 8]: leaf 4 at 349, out at 349 + 75 = 424
TEST_CASE("raypipe reference: hand-counted cycles on the hand scene", "[raypipe_cycles]") {
  const KdImage image = layOutKd(handKdScene());
  RaypipeConfig config;
  const KdRay a{{0.5f, 0.25f, 0.25f}, {1, 0, 0}, false};
  const KdRay b{{0.5f, 0.9f, 0.9f}, {1, 0, 0}, false};
  RaypipeCycleRun run = runRaypipeCycles(config, image, {{a, 0}});
  CHECK(run.results[0].hit);
  CHECK(run.results[0].primitive == 0);
  CHECK(run.results[0].exitCycle == 191);
  run = runRaypipeCycles(config, image, {{b, 0}});
  CHECK(run.results[0].hit);
  CHECK(run.results[0].primitive == 2);
  CHECK(run.results[0].counts.restarts == 0);
  CHECK(run.results[0].exitCycle == 399);
  // Nine rays like (a), issued every 3 cycles. Ray k is granted by tarb from SINT at G = 63 + 3k,
  // reaches TRAV at G + 5, offers node 1 to tarb at G + 24 and node 2 at G + 48, reaches leaf 2 at
  // G + 53 and leaves at G + 128. Ray 8's SINT offer (87) meets ray 0's node-1 offer from TRAV
  // (87): tarb's pointer, advanced in each of the 8 cycles with an offer before (63, 66, ... 84),
  // is back at input 0, so input 2 (TRAV) comes before input 3 (SINT): ray 0 is granted, ray 8
  // waits in its VS_buf and is granted at 88 (pointer 1): it leaves at 88 + 128 = 216, one cycle
  // late. No other offers meet (TRAV's at 87 ... 108 and 112, then 111 ... 132 and 136).
  {
    std::vector<RaypipeCycleRay> nine;
    for (uint32_t k = 0; k < 9; ++k) nine.push_back(RaypipeCycleRay{a, k});
    run = runRaypipeCycles(config, image, nine);
    for (uint32_t k = 0; k < 8; ++k) CHECK(run.results[k].exitCycle == 191 + 3 * k);
    CHECK(run.results[8].exitCycle == 216);
  }
  config.shortStackDepth = 1;
  run = runRaypipeCycles(config, image, {{b, 0}});
  CHECK(run.results[0].hit);
  CHECK(run.results[0].primitive == 2);
  CHECK(run.results[0].counts.restarts == 1);
  CHECK(run.results[0].counts.dropped == 1);
  CHECK(run.results[0].exitCycle == 424);
}

// With one ray id, rays cannot overlap: each ray's latency from the shader on is its latency
// alone, and the next ray enters SINT on the first v2 cycle once its id is back in the id FIFO
// (freed when the result enters the shader's VS pipe, 3 cycles before it leaves; shown 2 cycles
// after its write), so the frame is the sum of the single rays' latencies and those gaps.
TEST_CASE("raypipe reference: one ray in flight is the sum of single-ray latencies",
          "[raypipe_cycles]") {
  const KdImage image = builtImage(fewTriangles());
  const std::vector<RaypipeCycleRay> rays = mixedRays(image, 12, 5);
  RaypipeConfig config;
  config.raysInFlight = 1;
  const RaypipeCycleRun run = runRaypipeCycles(config, image, rays);
  int64_t expected = 44;  // the first ray into SINT, as in the hand count above
  for (size_t i = 0; i < rays.size(); ++i) {
    const RaypipeCycleRun alone = runRaypipeCycles(RaypipeConfig{}, image, {rays[i]});
    const int64_t latency = alone.results[0].exitCycle - alone.results[0].shaderInCycle;
    INFO("ray " << i);
    CHECK(run.results[i].shaderInCycle == expected);
    CHECK(run.results[i].exitCycle == expected + latency);
    int64_t next = run.results[i].exitCycle - 3 + 2;  // the id shown again
    while (next % 3 != 2) ++next;
    expected = next;
  }
  CHECK(run.maxRaysInFlight == 1);
}

TEST_CASE("raypipe reference: invariants with few ray ids", "[raypipe_cycles]") {
  const KdImage image = builtImage(sphereCorners({0, 0, 3}, 5, 8));
  const std::vector<RaypipeCycleRay> rays = mixedRays(image, 500, 9);
  RaypipeConfig config;
  const RaypipeCycleRun full = runRaypipeCycles(config, image, rays);
  config.raysInFlight = 4;
  const RaypipeCycleRun four = runRaypipeCycles(config, image, rays);
  CHECK(four.maxRaysInFlight == 4);
  CHECK(full.maxRaysInFlight > 4);
  CHECK(four.frameCycles > full.frameCycles);
  for (const RaypipeCycleRun* run : {&full, &four}) {
    std::vector<int> seen(rays.size(), 0);
    for (const RaypipeCycleResult& r : run->results) {
      CHECK(r.exitCycle >= 0);
      ++seen[r.pixelId];
    }
    for (int n : seen) CHECK(n == 1);
    for (const RaypipeFifoPeak& f : run->fifos) {
      INFO(f.fifo);
      CHECK(f.peak <= f.depth);
    }
    for (size_t i = 0; i < rays.size(); ++i) {
      CHECK(run->results[i].hit == four.results[i].hit);
      CHECK(floatBits(run->results[i].t) == floatBits(four.results[i].t));
    }
  }
  SECTION("refused settings") {
    RaypipeConfig three;
    three.traversalUnits = 3;  // the shortstack and the list unit have ports for two
    CHECK_THROWS_AS(runRaypipeCycles(three, image, rays), std::invalid_argument);
  }
}

TEST_CASE("raypipe reference: a frame at 20x15 and 40x30", "[raypipe_cycles]") {
  const KdImage image = frameScene();
  for (int level : {0, 1}) {
    const std::vector<RaypipeCycleRay> rays = prgRays(level);
    const RaypipeCycleRun run = runRaypipeCycles(RaypipeConfig{}, image, rays);
    std::vector<int> seen(rays.size(), 0);
    int hits = 0;
    for (const RaypipeCycleResult& r : run.results) {
      ++seen.at(r.pixelId);
      hits += r.hit ? 1 : 0;
    }
    for (int n : seen) CHECK(n == 1);
    CHECK(hits > 0);
    // The PRG's 1 ray in 3 cycles bounds the frame from below.
    CHECK(run.frameCycles > 3 * static_cast<int64_t>(rays.size()));
  }
  // The PRG's rays (|d| >= 240: the as-built clamp's t_max = 1) against the golden traversal.
  RaypipeConfig config;
  for (int depth : {4, 2}) {
    config.shortStackDepth = depth;
    CHECK(checkAgainstGolden(image, prgRays(1), config).hits > 50);
  }
}

// Not run by default: the figures docs/raypipe.md quotes.
TEST_CASE("raypipe reference: frame figures", "[.raypipe_figures]") {
  const KdImage image = frameScene();
  for (int level : {0, 2, 3, 4, 5}) {
    const std::vector<RaypipeCycleRay> rays = prgRays(level);
    const RaypipeCycleRun run = runRaypipeCycles(RaypipeConfig{}, image, rays);
    int hits = 0, boxMisses = 0;
    for (const RaypipeCycleResult& r : run.results) {
      hits += r.hit ? 1 : 0;
      boxMisses += r.boxMiss ? 1 : 0;
    }
    std::printf("%dx%d: %zu rays, %d hits, %d box misses: frame %lld cycles, host %.3f s\n",
                20 << level, 15 << level, rays.size(), hits, boxMisses,
                static_cast<long long>(run.frameCycles), run.hostSeconds);
    for (const RaypipeUnitActivity& a : run.units)
      std::printf("  %-14s busy %8lld stall %8lld\n", a.unit.c_str(),
                  static_cast<long long>(a.busy), static_cast<long long>(a.stall));
    for (const RaypipeFifoPeak& f : run.fifos)
      if (f.peak > 0) std::printf("  %-18s peak %3d of %d\n", f.fifo.c_str(), f.peak, f.depth);
  }
}

// The VGA reader's window, counted from vga.sv's and fbh_reader's rules (raypipe_vga.h): after n
// 50 MHz edges the 25 MHz counters have advanced (n + 1) / 2 times; the first screen row is line
// 31, where vga_col = 0x3ff is clk_cnt 143: (n + 1) / 2 = 31 * 800 + 143 = 24943 first at n =
// 49885, so fbh_active is on from cycle 49886, which reads (the one-hot register at 0001), then
// every other cycle: 639 reads in the row's 1278 active cycles, 480 rows a screen of 833,600
// cycles.
TEST_CASE("raypipe reference: the VGA reader's window", "[raypipe_cycles]") {
  raypipe_ref::VgaReader vga;
  int64_t first = -1, reads = 0, inFirstRow = 0, twice = 0;
  bool previous = false;
  for (int64_t n = 0; n < 833600; ++n) {
    const bool reading = vga.reading();
    if (reading && first < 0) first = n;
    if (reading) ++reads;
    if (reading && n < 49886 + 1600) ++inFirstRow;
    if (reading && previous) ++twice;  // never two cycles in a row
    previous = reading;
    vga.tick();
  }
  CHECK(twice == 0);
  CHECK(first == 49886);
  CHECK(inFirstRow == 639);
  CHECK(reads == 480 * 639);
}

TEST_CASE("raypipe reference: the pixel writer waits out the VGA reader", "[raypipe_cycles]") {
  const KdImage image = builtImage(sphereCorners({1.125, 1.125, 1.5}, 5, 10));
  const std::vector<RaypipeCycleRay> rays = prgRays(0);
  const RaypipeCycleRun free = runRaypipeCycles(RaypipeConfig{}, image, rays);
  RaypipeCycleOptions options;
  RaypipePixelWriter& writer = options.writer;
  writer.vgaReadWindow = true;
  writer.vgaPhase = 49886;  // cycle 0 is the first cycle of the screen's first active row
  const RaypipeCycleRun vga = runRaypipeCycles(RaypipeConfig{}, image, rays, options);
  CHECK(vga.writerWaits > 0);
  CHECK(vga.lastWriteCycle >= free.lastWriteCycle);
  // This frame's exits never fill the 20 entries when the writer gets every other cycle: the exits
  // do not move. (Bursts can fill it: exits come one a cycle when rays queue behind the one
  // traversal unit, as the RTL recording of t4s3 at 160x120 shows, test_raypipe_rtl.cpp.)
  for (size_t i = 0; i < rays.size(); ++i)
    CHECK(vga.results[i].exitCycle == free.results[i].exitCycle);
  writer.vgaPhase += raypipe_ref::VgaReader::kScreenCycles;  // a screen later: the same
  const RaypipeCycleRun again = runRaypipeCycles(RaypipeConfig{}, image, rays, options);
  CHECK(again.lastWriteCycle == vga.lastWriteCycle);
  CHECK(again.writerWaits == vga.writerWaits);
  writer.vgaPhase = -1;
  CHECK_THROWS_AS(runRaypipeCycles(RaypipeConfig{}, image, rays, options), std::invalid_argument);
}

}  // namespace rtu
