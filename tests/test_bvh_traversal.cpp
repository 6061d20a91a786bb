// The golden BVH traversal (kinds/bvh/bvh_traversal.h) on a hand-laid image of three nodes and
// three triangles, every count and state derived by hand below; the access-width contract (every
// word a state reads lies in one aligned 4-word access); the first of equal hits winning.
#include <catch2/catch.hpp>

#include <vector>

#include "access_width_check.h"
#include "base/float_bits.h"
#include "kinds/bvh/bvh_kind.h"
#include "rtu/golden_shell.h"

namespace rtu {
namespace {

using WatertightBvh = BvhKind<WatertightIntersector>;

void appendNode(std::vector<uint32_t>& words, Vec3<float> lower, Vec3<float> upper, uint32_t w6,
                uint32_t w7) {
  for (float c : {lower.x, lower.y, lower.z, upper.x, upper.y, upper.z})
    words.push_back(floatBits(c));
  words.push_back(w6);
  words.push_back(w7);
}

void appendTriangle(std::vector<uint32_t>& words, std::array<Vec3<float>, 3> v, uint32_t id) {
  for (const auto& p : v)
    for (int k = 0; k < 3; ++k) words.push_back(floatBits(p[k]));
  words.insert(words.end(), {id, 0, 0});
}

// Nodes at word 0: the root over [0,0,1]-[3,3,3] with children 1 and 2; node 1 a leaf of
// reference 0 over triangle 0 (z = 1, legs 2 along x and y from the origin); node 2 a leaf of
// references 1 and 2 over triangles 2 (z = 2, legs 1 from (2, 0)) then 1 (z = 3, legs 2 from
// (1, 1)). References at word 24: 0, 2, 1 and a pad; triangles at word 28, ids 100 + index.
struct HandImage {
  std::vector<uint32_t> words;
  BvhSections sections{0, 24, 28};

  HandImage() {
    appendNode(words, {0, 0, 1}, {3, 3, 3}, 1, 2);
    appendNode(words, {0, 0, 1}, {2, 2, 1}, 0, kBvhLeafBit | 1);
    appendNode(words, {1, 0, 2}, {3, 3, 3}, 1, kBvhLeafBit | 2);
    words.insert(words.end(), {0, 2, 1, 0});
    appendTriangle(words, {{{0, 0, 1}, {2, 0, 1}, {0, 2, 1}}}, 100);
    appendTriangle(words, {{{1, 1, 3}, {3, 1, 3}, {1, 3, 3}}}, 101);
    appendTriangle(words, {{{2, 0, 2}, {3, 0, 2}, {2, 1, 2}}}, 102);
  }
};

// Straight down from z = 4 through (x, y): x and y directions are 0, so a box is hit only when
// (x, y) lies strictly inside its footprint, and then from t = 4 - top to t = 4 - bottom.
BvhJob down(const HandImage& image, float x, float y) {
  return BvhJob{makeBvhRay({x, y, 4}, {0, 0, -1}, 0, 100), image.sections};
}

BvhResult trace(const HandImage& image, const BvhJob& job, BvhConfig config = {}) {
  GoldenShell<WatertightBvh> shell(WordMemory(image.words), config);
  BvhResult result;
  shell.run(7, job, result);
  return result;
}

}  // namespace

TEST_CASE("BVH traversal: a ray outside the root box", "[bvh_traversal]") {
  const HandImage image;
  const BvhResult result = trace(image, down(image, 5, 5));
  CHECK_FALSE(result.hit);
  CHECK(result.idWord == 7);
  CHECK(result.cost == 3);  // ROOT0, ROOT1, ROOT_TEST
  CHECK(result.counts.nodes == 1);
  CHECK(result.counts.boxTests == 1);
  CHECK(result.counts.triangleTests == 0);
}

TEST_CASE("BVH traversal: one child hit, its leaf's triangle hit", "[bvh_traversal]") {
  const HandImage image;
  const BvhResult result = trace(image, down(image, 0.25f, 0.25f));  // node 1's footprint only
  CHECK(result.hit);
  CHECK(result.t == 3.0f);
  CHECK(result.primitive == 100);
  CHECK(result.u == 0.125f);  // (0.25, 0.25) over legs of 2
  CHECK(result.v == 0.125f);
  // ROOT0, ROOT1, ROOT_TEST, LEFT0, LEFT1, RIGHT0, RIGHT1, DECIDE, REF, TRI0-2, TEST, POP.
  CHECK(result.cost == 14);
  CHECK(result.counts.nodes == 3);
  CHECK(result.counts.boxTests == 3);
  CHECK(result.counts.triangleTests == 1);
  CHECK(result.counts.pushes == 0);
  CHECK(result.counts.pops == 0);
}

TEST_CASE("BVH traversal: the near leaf's hit culls the pushed far child", "[bvh_traversal]") {
  const HandImage image;
  // Both footprints: node 2 entered at t = 1 before node 1 at t = 3, which is pushed. Triangle 2
  // misses (x < 2), triangle 1 hits at t = 1, so the popped entry at 3 is skipped.
  const BvhResult result = trace(image, down(image, 1.25f, 1.25f));
  CHECK(result.hit);
  CHECK(result.t == 1.0f);
  CHECK(result.primitive == 101);
  CHECK(result.u == 0.125f);
  CHECK(result.v == 0.125f);
  CHECK(result.cost == 8 + 5 + 5 + 2);  // to DECIDE, two triangles, POP (skip), POP (empty)
  CHECK(result.counts.triangleTests == 2);
  CHECK(result.counts.pushes == 1);
  CHECK(result.counts.pops == 1);
  CHECK(result.counts.boxTests == 3);
}

TEST_CASE("BVH traversal: the near leaf misses and the popped far child hits", "[bvh_traversal]") {
  const HandImage image;
  // Both footprints; neither triangle of node 2 lies under (1.25, 0.25); triangle 0 does.
  const BvhResult result = trace(image, down(image, 1.25f, 0.25f));
  CHECK(result.hit);
  CHECK(result.t == 3.0f);
  CHECK(result.primitive == 100);
  CHECK(result.u == 0.625f);
  CHECK(result.v == 0.125f);
  CHECK(result.cost == 8 + 5 + 5 + 1 + 5 + 1);  // ..., POP (node 1), its triangle, POP (empty)
  CHECK(result.counts.triangleTests == 3);
  CHECK(result.counts.pushes == 1);
  CHECK(result.counts.pops == 1);
}

TEST_CASE("BVH traversal: box and triangle units of several cycles, counted by hand",
          "[bvh_traversal]") {
  // Box tests 3 cycles (ROOT_TEST, DECIDE); a leaf's tests 2 apart (the interval) but for its
  // last, which waits the latency 7; every other state 1 (bvh_timing.h).
  const HandImage image;
  BvhConfig config;
  config.cycles = BvhCycles{3, 7, 2};
  // ROOT0, ROOT1 (2), ROOT_TEST (3).
  CHECK(trace(image, down(image, 5, 5), config).cost == 5);
  // To DECIDE: 2 + 3 + LEFT0..RIGHT1 (4) + DECIDE (3) = 12; REF, TRI0-2 (4), TEST (last: 7),
  // POP (1).
  CHECK(trace(image, down(image, 0.25f, 0.25f), config).cost == 12 + 4 + 7 + 1);
  // Node 2's two triangles: 4 + TEST (2) + 4 + TEST (7), a leaf of k = 2 spending
  // (k - 1) 2 + 7 in TEST; then POP (skip), POP (empty).
  CHECK(trace(image, down(image, 1.25f, 1.25f), config).cost == 12 + 17 + 2);
  // ..., POP (node 1), its one triangle (4 + 7), POP (empty).
  CHECK(trace(image, down(image, 1.25f, 0.25f), config).cost == 12 + 17 + 1 + 11 + 1);
}

TEST_CASE("BVH traversal: the axis order agrees here, the children's centres apart along z",
          "[bvh_traversal]") {
  const HandImage image;
  BvhConfig axis;
  axis.childOrder = ChildOrder::Axis;
  // Node 2's centre is above node 1's and the ray goes down: node 2 first, as by entry.
  const BvhResult result = trace(image, down(image, 1.25f, 1.25f), axis);
  CHECK(result.primitive == 101);
  CHECK(result.cost == 20);
  SECTION("going up, node 1 first, then node 2 pushed and culled beyond the hit") {
    const BvhJob up{makeBvhRay({1.25f, 0.25f, 0}, {0, 0, 1}, 0, 100), image.sections};
    const BvhResult fromBelow = trace(image, up, axis);
    CHECK(fromBelow.primitive == 100);
    CHECK(fromBelow.t == 1.0f);
    CHECK(fromBelow.cost == 8 + 5 + 2);
  }
}

TEST_CASE("BVH traversal: every state reads within one aligned access", "[bvh_traversal]") {
  const HandImage image;
  WatertightBvh::Behaviour traversal = WatertightBvh::behaviour(BvhConfig{});
  traversal.start(down(image, 1.25f, 0.25f));
  const int reads = wordsReadWithinAccesses(traversal, WordMemory(image.words));
  // 6 node accesses of 4 words, 3 references, 3 triangles of 3 accesses of 4 words.
  CHECK(reads == 6 * 4 + 3 + 3 * 3 * 4);
}

TEST_CASE("BVH traversal: of equal hits in a leaf, the first referenced wins", "[bvh_traversal]") {
  HandImage image;
  // A root leaf of references 1, 0 over two triangles in the plane z = 1 that overlap.
  image.words.clear();
  appendNode(image.words, {0, 0, 1}, {3, 3, 1}, 0, kBvhLeafBit | 2);  // the root, a leaf
  image.words.resize(24, 0);
  image.words.insert(image.words.end(), {1, 0, 0, 0});
  appendTriangle(image.words, {{{0, 0, 1}, {2, 0, 1}, {0, 2, 1}}}, 100);
  appendTriangle(image.words, {{{0, 0, 1}, {3, 0, 1}, {0, 3, 1}}}, 101);
  const BvhResult result = trace(image, down(image, 0.5f, 0.5f));
  CHECK(result.primitive == 101);  // referenced first
  CHECK(result.t == 3.0f);
  CHECK(result.cost == 3 + 5 + 5 + 1);
}

}  // namespace rtu
