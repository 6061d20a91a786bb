// The resource estimate (issue 30 §2; docs/comparison.md, "Resources"): the block-RAM and DSP48E
// rules on hand-tiled cases, and each architecture on a small configuration whose bits and units
// are counted by hand in the comments.
#include <catch2/catch.hpp>

#include "explore/architecture_resources.h"
#include "kinds/bih/bih_resources.h"
#include "kinds/bvh/bvh_resources.h"
#include "kinds/kd/kd_resources.h"
#include "kinds/svo/svo_resources.h"
#include "raypipe/raypipe_resources.h"
#include "rtu/resource_estimate.h"
#include "sim/rtu_resources.h"

namespace rtu {

TEST_CASE("Block RAMs tile an array over the RAMB18's best aspect ratio", "[resources]") {
  CHECK(blockRamsOf(64, 1000) == 0);  // 64 words: registers or LUT RAM
  CHECK(blockRamsOf(65, 1) == 1);
  CHECK(blockRamsOf(512, 36) == 1);
  // 1024 x 32: 1K x 18 twice, or 512 x 36 twice; 2K x 9 would take 4, 16K x 1 32.
  CHECK(blockRamsOf(1024, 32) == 2);
  // 512 x 384: 512 x 36 eleven times (384 / 36 = 10.7), 1K x 18 22 times.
  CHECK(blockRamsOf(512, 384) == 11);
  // 1024 x 256: 1K x 18 fifteen times (256 / 18 = 14.2), 512 x 36 2 x 8 = 16 times.
  CHECK(blockRamsOf(1024, 256) == 15);
}

TEST_CASE("DSP48E slices tile a multiplier's operands over 25 x 18", "[resources]") {
  const auto fixed = [](int a, int b) {
    return dsp48eOf({"", ArithmeticKind::Multiplier, NumberKind::Fixed, a, 1, b});
  };
  CHECK(fixed(25, 18) == 1);
  CHECK(fixed(18, 25) == 1);  // turned to fit
  CHECK(fixed(32, 32) == 4);  // 2 x 2
  // 31 x 48: 48 on the 25-bit side is 2 x 2 = 4; 31 there would be 2 x 3 = 6.
  CHECK(fixed(31, 48) == 4);
  CHECK(dsp48eOf({"", ArithmeticKind::Multiplier, NumberKind::Float, 32, 1}) == 2);  // 24 x 24
  CHECK(dsp48eOf({"", ArithmeticKind::Adder, NumberKind::Float, 32, 1}) == 0);
  CHECK(dsp48eOf({"", ArithmeticKind::Divider, NumberKind::Fixed, 32, 1}) == 0);
}

TEST_CASE("An SVO RTU with ideal memory: stacks\\, the scene on chip\\, result buffers",
          "[resources]") {
  RtuConfig config;
  config.core = "svo";
  config.cores = 2;
  GoldenConfig& svo = config.coreConfig<SvoKind>();
  svo.format = {16, 8};
  svo.stackFrames = 2;
  const ResourceEstimate estimate = rtuResources(config, 1000);
  // A frame: entry 32 + 9 values x 16 + child 3 = 179 bits; 2 frames a core, 2 cores: 716.
  // The scene: 1,000 words x 32 = 32,000 bits, 1K x 18 twice. Results: a 32-byte record a core
  // (the thesis' result at up to 32 bits), 2 x 256 = 512 bits in registers.
  CHECK(estimate.memoryBits() == 716 + 32000 + 512);
  CHECK(estimate.blockRams() == 2);
  CHECK(estimate.blockRamBits() == 32000);
  // A core: 3 midpoint adders and 8 comparators of 16 bits; no multiplier (the thesis' 0 DSP).
  CHECK(estimate.unitCount(ArithmeticKind::Adder) == 6);
  CHECK(estimate.unitCount(ArithmeticKind::Comparator) == 16);
  CHECK(estimate.unitCount(ArithmeticKind::Multiplier) == 0);
  CHECK(estimate.unitCount(ArithmeticKind::Divider) == 0);
  CHECK(estimate.dsp48e() == 0);
  CHECK(estimate.luts() == 22 * 16);  // a LUT a bit of each adder and comparator
}

TEST_CASE("A BVH RTU with caches and shared triangle units", "[resources]") {
  RtuConfig config;
  config.core = "bvh";
  config.cores = 4;
  config.triangleSharedBy = 2;
  config.coreConfig<BvhKind<>>().stackDepth = 4;
  config.memory.ideal = false;
  config.memory.l1 = CacheConfig{1024, 32, 2};
  config.memory.l2 = CacheConfig{4096, 64, 4};
  const ResourceEstimate estimate = rtuResources(config, 1000);
  // Stacks: 4 entries x 96 bits x 4 cores = 1,536.
  // L1 a core: data 1,024 B = 128 x 64 bits = 8,192 (512 x 36 twice); 16 sets of 2 ways, the tag
  // 32 - 4 set bits - 5 offset bits = 23 and a valid bit: 16 x 2 x 24 = 768 in LUT RAM.
  // L2: data 4,096 B = 512 x 64 = 32,768 bits (2 RAMB18); 16 sets of 4 ways, tag 32 - 4 - 6 = 22:
  // 16 x 4 x 23 = 1,472. Results: 32 bytes a core, 4 x 256 = 1,024. No scene on chip.
  CHECK(estimate.memoryBits() == 1536 + 4 * (8192 + 768) + 32768 + 1472 + 1024);
  CHECK(estimate.blockRams() == 4 * 2 + 2);
  // 4 cores' box units (12 adders, 12 multipliers, 22 comparators each) and 2 watertight units
  // (22 adders, 18 multipliers, 1 divider, 6 comparators each), all binary32.
  CHECK(estimate.unitCount(ArithmeticKind::Multiplier) == 4 * 12 + 2 * 18);
  CHECK(estimate.unitCount(ArithmeticKind::Adder) == 4 * 12 + 2 * 22);
  CHECK(estimate.unitCount(ArithmeticKind::Divider) == 2);
  CHECK(estimate.unitCount(ArithmeticKind::Comparator) == 4 * 22 + 2 * 6);
  CHECK(estimate.dsp48e() == 2 * 84);  // two a binary32 multiplier
}

TEST_CASE("Moller-Trumbore's triangle unit has more multipliers than the watertight one",
          "[resources]") {
  BvhConfig config;
  config.triangleTest = TriangleTest::MollerTrumbore;
  // edges 6 subtractions; P = D x e2 6 multiplications, 3 subtractions; det, u, v, t dot products
  // 3 multiplications and 2 additions each; T 3 subtractions; Q = T x e1 6 and 3; 1 / det; u, v,
  // t scaled 3 multiplications; u + v 1 addition.
  const CoreResources resources = coreResources(config);
  CHECK(resources.triangleUnit.unitCount(ArithmeticKind::Multiplier) == 6 + 4 * 3 + 6 + 3);
  CHECK(resources.triangleUnit.unitCount(ArithmeticKind::Adder) == 6 + 3 + 4 * 2 + 3 + 3 + 1);
}

TEST_CASE("A two-level BVH core adds its transform unit", "[resources]") {
  // XFORM's toModelSpace, binary32: the origin o - T (3 subtractions), each row of R^T times it
  // (3 multiplications, 2 additions) and by its 1/S (1 multiplication); the direction the same
  // without the subtraction; the reciprocal direction 3 comparisons with 2^-64 and 3 divisions.
  const BvhConfig config;
  const CoreResources one = coreResources(config), two = twoLevelCoreResources(config);
  const auto added = [&](ArithmeticKind kind) {
    return two.core.unitCount(kind) - one.core.unitCount(kind);
  };
  CHECK(added(ArithmeticKind::Multiplier) == 3 * (3 + 1) + 3 * (3 + 1));
  CHECK(added(ArithmeticKind::Adder) == 3 + 3 * 2 + 3 * 2);
  CHECK(added(ArithmeticKind::Divider) == 3);
  CHECK(added(ArithmeticKind::Comparator) == 3);
  CHECK(two.core.memoryBits() == one.core.memoryBits());
  CHECK(two.triangleUnit.unitCount(ArithmeticKind::Multiplier) ==
        one.triangleUnit.unitCount(ArithmeticKind::Multiplier));
  // In an RTU: one a core, 2 DSP48E a binary32 multiplier.
  RtuConfig rtu;
  rtu.core = "bvh";
  rtu.cores = 4;
  CHECK(rtuResources(rtu, 100, two).dsp48e() == rtuResources(rtu, 100).dsp48e() + 4 * 24 * 2);
}

TEST_CASE("A BIH core of seed 004's formats: 48 DSP48E of the seed's 52", "[resources]") {
  RtuConfig config;
  config.core = "bih";
  config.cores = 1;
  config.coreConfig<BihKind<>>().format = kC99Format;  // n 29, m 32, C 16
  const ResourceEstimate estimate = rtuResources(config, 0);
  // The plane distances: 2 multipliers of n + 2 = 31 by m + C = 48 bits, 4 DSP48E each; the
  // triangle unit's 10 multipliers of 32 x 32, 4 each: 8 + 40.
  CHECK(estimate.unitCount(ArithmeticKind::Multiplier) == 12);
  CHECK(estimate.dsp48e() == 48);
  CHECK(estimate.unitCount(ArithmeticKind::Divider) == 1);  // t_div
  CHECK(estimate.unitCount(ArithmeticKind::Adder) == 2 + 10);
  CHECK(estimate.unitCount(ArithmeticKind::Comparator) == 4 + 5);
  // The stack: 32 node triples of 96 bits (LUT RAM), an empty scene, one 48-byte result.
  CHECK(estimate.memoryBits() == 32 * 96 + 384);
  CHECK(estimate.blockRams() == 0);
}

TEST_CASE("A k-d core: seed 001's SINT\\, TRAV and INT in binary32", "[resources]") {
  KdTraversalConfig config;
  config.stackDepth = 2;
  const CoreResources resources = coreResources(config);
  // The short stack's 2 entries and the restart node, 48 bits each.
  CHECK(resources.core.memoryBits() == 3 * 48);
  CHECK(resources.core.unitCount(ArithmeticKind::Divider) == 3);     // SINT 2, TRAV 1
  CHECK(resources.core.unitCount(ArithmeticKind::Comparator) == 8);  // SINT 5, TRAV 3
  CHECK(resources.core.unitCount(ArithmeticKind::Multiplier) == 0);
  // INT, the RTL's: 20 multipliers, 18 adders, 1 divider, 3 comparators.
  CHECK(resources.triangleUnit.unitCount(ArithmeticKind::Multiplier) == 20);
  CHECK(resources.triangleUnit.dsp48e() == 40);
  CHECK(resources.triangleUnit.luts() == 20 * 80 + 18 * 390 + 800 + 3 * 40);
}

TEST_CASE("The ray pipe's final build: 1.31 Mbit in 82 RAMB18\\, 31 multipliers", "[resources]") {
  const ResourceEstimate estimate = raypipeResources(RaypipeConfig{});
  // Caches: tcache 512 x 384 = 196,608 (11), lcache 1024 x 256 = 262,144 (15), icache 1024 x
  // 288 = 294,912 (16). FIFOs: PRG 16 x 211 = 3,376, SINT 18 x (96 + 48 + 28) = 3,096, tarb 512
  // x 96 = 49,152 (3), larb 512 x 37 = 18,944 (2), TRAV leaf 8 x 41 = 328 and math 15 x 144 =
  // 2,160, INT list 256 x 129 = 33,024 (4), larb 256 x 36 = 9,216 (1), shader 46 x 9 = 414,
  // pixel buffer 20 x 35 = 700. Per ray: 3 ray stores 512 x 192 = 294,912 (6 each, 18), 4 stack
  // slots 512 x 48 = 98,304 (2 each, 8), restart 512 x 48 = 24,576 (2), ray ids 512 x 9 = 4,608
  // (1), pixel ids 512 x 19 = 9,728 (1).
  CHECK(estimate.memoryBits() == 753664 + 120410 + 432128);
  CHECK(estimate.blockRams() == 11 + 15 + 16 + 3 + 2 + 4 + 1 + 18 + 8 + 2 + 1 + 1);
  // PRG 11 + INT 20 multipliers; adders PRG 8, SINT 2, TRAV 1, INT 18; dividers SINT 2, TRAV 1,
  // INT 1; comparators SINT 5, TRAV 3, INT 3, short stack 1, list 1.
  CHECK(estimate.unitCount(ArithmeticKind::Multiplier) == 31);
  CHECK(estimate.dsp48e() == 62);
  CHECK(estimate.unitCount(ArithmeticKind::Adder) == 29);
  CHECK(estimate.unitCount(ArithmeticKind::Divider) == 4);
  CHECK(estimate.unitCount(ArithmeticKind::Comparator) == 13);
}

TEST_CASE("A second traversal unit adds its FIFOs\\, ray store and units", "[resources]") {
  RaypipeConfig two;
  two.traversalUnits = 2;
  const ResourceEstimate one = raypipeResources(RaypipeConfig{}), more = raypipeResources(two);
  // leaf FIFO 328 + math FIFO 2,160 + a ray store 98,304 bits; 1 adder, 1 divider, 3 comparators.
  CHECK(more.memoryBits() - one.memoryBits() == 328 + 2160 + 98304);
  CHECK(more.unitCount(ArithmeticKind::Comparator) - one.unitCount(ArithmeticKind::Comparator) ==
        3);
  CHECK(more.unitCount(ArithmeticKind::Divider) - one.unitCount(ArithmeticKind::Divider) == 1);
}

TEST_CASE("A row's resources: the totals as columns and the rate per resource", "[resources]") {
  ResourceEstimate estimate;
  estimate.memories = {{"fifo", 100, 10, 2}, {"registers", 4, 8, 1}};
  estimate.units = {{"unit", ArithmeticKind::Multiplier, NumberKind::Fixed, 32, 3},
                    {"unit", ArithmeticKind::Adder, NumberKind::Fixed, 8, 2}};
  const nlohmann::ordered_json row = {{"resources", resourcesJson(estimate)}};
  // 2 x 100 x 10 + 4 x 8 = 2,032 bits, 2,000 of them in 2 RAMB18 (100 words each); 3 x 4
  // DSP48E; 2 adders of 8 bits: 16 LUTs.
  CHECK(resourceValues(row) ==
        std::vector<std::string>{"2032", "2000", "2", "12", "3", "2", "0", "0", "16"});
  CHECK(resourceValues(nlohmann::ordered_json::object()) == std::vector<std::string>(9, ""));
  CHECK(perResource(60.0, 12).get<double>() == 5.0);
  CHECK(perResource(60.0, 0).is_null());  // none of the resource: no rate per it
}

}  // namespace rtu
