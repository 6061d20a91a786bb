// Tiny hand-built trees whose per-ray results and costs were worked out by hand from the RTL's
// state sequence (appendix C.4). Every case uses a job with exactly representable t-values:
// t0 = (-8, -8, 2), t1 = (8, 8, 4), so tm = (0, 0, 3): a ray travelling along +z through the
// centre line of the cube. INIT picks child 3 (entry plane z, and t0z = 2 >= tm.x, tm.y).
#include <catch2/catch.hpp>

#include <vector>

#include "kinds/svo/golden_model.h"
#include "kinds/svo/ray_setup.h"
#include "svo_descriptor.h"

using namespace rtu;

namespace {

TValueRecord centreLineJob() {
  TValueRecord job;
  job.id = 42;
  job.t0Bits = {floatBits(-8.0f), floatBits(-8.0f), floatBits(2.0f)};
  job.t1Bits = {floatBits(8.0f), floatBits(8.0f), floatBits(4.0f)};
  return job;
}

TraversalResult trace(const std::vector<uint32_t>& image, const TValueRecord& job,
                      int stackFrames = kRtlStackFrames) {
  GoldenConfig config;
  config.stackFrames = stackFrames;
  GoldenModel model(WordMemory(image), config);
  return model.trace(job);
}

constexpr int64_t kOne = 0x10000;

}  // namespace

TEST_CASE("Full root: INIT, EVAL hit", "[traversal]") {
  const TraversalResult result = trace({descriptor(false, 0, 0xFF, 0xFF)}, centreLineJob());
  REQUIRE(result.hit);
  REQUIRE(result.cost == 2);
  REQUIRE(result.tHit == 2 * kOne);  // child 3's t0 = (tm.x, tm.y, t0.z) = (0, 0, 2): max is z
  REQUIRE(result.normal == std::array<int64_t, 3>{0, 0, kOne});
  REQUIRE(result.idWord == 42);
}

TEST_CASE("Empty root: INIT, EVAL, NEXT (to 7), EVAL, NEXT (end), miss", "[traversal]") {
  const TraversalResult result = trace({descriptor(false, 0, 0x00, 0x00)}, centreLineJob());
  REQUIRE_FALSE(result.hit);
  REQUIRE(result.cost == 5);
  REQUIRE(result.tHit == 0);
  REQUIRE(result.normal == std::array<int64_t, 3>{0, 0, 0});
}

TEST_CASE("A ray that misses the cube: INIT, EVAL, miss", "[traversal]") {
  TValueRecord job = centreLineJob();
  job.t0Bits = {floatBits(5.0f), floatBits(0.0f), floatBits(0.0f)};
  job.t1Bits = {floatBits(6.0f), floatBits(1.0f), floatBits(1.0f)};  // max t0 5 >= min t1 1
  const TraversalResult result = trace({descriptor(false, 0, 0xFF, 0xFF)}, job);
  REQUIRE_FALSE(result.hit);
  REQUIRE(result.cost == 2);
}

TEST_CASE("One push: INIT EVAL NEXT EVAL PUSH INIT EVAL", "[traversal]") {
  // Root: child 7 is a node (descriptor at word 1) whose child 0 is solid.
  const std::vector<uint32_t> image = {descriptor(false, 1, 0x80, 0x00),
                                       descriptor(false, 0, 0x01, 0x01)};
  const TraversalResult result = trace(image, centreLineJob());
  REQUIRE(result.hit);
  REQUIRE(result.cost == 7);
  // In child 7: t0 = (0, 0, 3), tm = (4, 4, 3.5); INIT picks child 0 whose t0 is (0, 0, 3).
  REQUIRE(result.tHit == 3 * kOne);
  REQUIRE(result.normal == std::array<int64_t, 3>{0, 0, kOne});
}

namespace {

// Root with node children 3 and 7. Inside child 3 only sub-child 1 is solid, which the ray
// misses: it enters sub-child 0, moves to 4 and leaves, so the core pops back to the root.
// Cost: INIT EVAL PUSH | INIT EVAL NEXT EVAL NEXT POP | NEXT EVAL = 11 before child 7.
std::vector<uint32_t> popImage(bool far, uint32_t firstChild, size_t size) {
  std::vector<uint32_t> image(size, 0);
  image[0] = far ? descriptor(true, 1, 0x88, 0x00) : descriptor(false, firstChild, 0x88, 0x00);
  if (far) image[1] = firstChild;
  image[firstChild] = descriptor(false, 0, 0x02, 0x02);      // child 3
  image[firstChild + 1] = descriptor(false, 0, 0x01, 0x01);  // child 7
  return image;
}

}  // namespace

TEST_CASE("Pop back to the parent and continue", "[traversal]") {
  const TraversalResult result = trace(popImage(false, 1, 3), centreLineJob());
  // Child 7 in the root is a node: PUSH INIT EVAL (hit child 0) follow.
  REQUIRE(result.hit);
  REQUIRE(result.cost == 14);
  REQUIRE(result.tHit == 3 * kOne);
}

TEST_CASE("Far pointers: offset word, child offset from the descriptor", "[traversal]") {
  // The far word 0x300 has bits 9:8 set; the RTL would count them as valid children (defect 3)
  // and land on 0x302, an empty trap. Counting from the descriptor reaches child 7 at 0x301.
  std::vector<uint32_t> image = popImage(true, 0x300, 0x310);
  image[0x302] = descriptor(false, 0, 0x00, 0x00);
  const TraversalResult result = trace(image, centreLineJob());
  REQUIRE(result.hit);
  REQUIRE(result.cost == 14);  // a far push takes one PUSH cycle, like a near one
  REQUIRE(result.tHit == 3 * kOne);
}

TEST_CASE("Stack overflow is flagged, never silent", "[traversal]") {
  // Every node has eight node children that share the block of the level below, so any ray that
  // enters pushes once per level; the last level is solid.
  const int levels = 5;
  std::vector<uint32_t> image = {descriptor(false, 1, 0xFF, 0x00)};
  for (int level = 1; level <= levels; ++level)
    for (uint32_t slot = 0; slot < 8; ++slot)
      image.push_back(level < levels ? descriptor(false, 8 - slot, 0xFF, 0x00)
                                     : descriptor(false, 0, 0xFF, 0xFF));
  const TraversalResult deepEnough = trace(image, centreLineJob(), levels);
  REQUIRE(deepEnough.hit);
  REQUIRE_FALSE(deepEnough.stackOverflow);
  REQUIRE(deepEnough.cost == 2 + 3 * levels);  // INIT EVAL, then PUSH INIT EVAL per level
  const TraversalResult overflow = trace(image, centreLineJob(), levels - 1);
  REQUIRE(overflow.stackOverflow);
  REQUIRE_FALSE(overflow.hit);
}

TEST_CASE("Next-child selection equals the RTL lookup table", "[traversal]") {
  // get_next_child_idx's table from appendix C.4: row = current child, column = exit axis.
  const int table[8][3] = {{1, 2, 4}, {8, 3, 5}, {3, 8, 6}, {8, 8, 7},
                           {5, 6, 8}, {8, 7, 8}, {7, 8, 8}, {8, 8, 8}};
  for (int child = 0; child < 8; ++child)
    for (int axis = 0; axis < 3; ++axis) {
      std::array<int64_t, 3> t1{10, 10, 10};
      t1[axis] = 5;
      REQUIRE(nextChildIndex(child, t1) == table[child][axis]);
    }
  // Ties: x before y before z.
  REQUIRE(nextChildIndex(0, std::array<int64_t, 3>{5, 5, 5}) == 1);
  REQUIRE(nextChildIndex(0, std::array<int64_t, 3>{6, 5, 5}) == 2);
}

TEST_CASE("Initial child follows table 4.2 with >=", "[traversal]") {
  using V = std::array<int64_t, 3>;
  REQUIRE(initialChildIndex(V{4, 1, 1}, V{3, 5, 5}) == 0);  // entry x, passed neither midpoint
  REQUIRE(initialChildIndex(V{4, 1, 1}, V{3, 5, 3}) == 4);  // t0x >= tmz
  REQUIRE(initialChildIndex(V{4, 1, 1}, V{3, 4, 5}) == 2);  // t0x >= tmy holds with equality
  REQUIRE(initialChildIndex(V{1, 4, 1}, V{5, 3, 5}) == 0);
  REQUIRE(initialChildIndex(V{1, 4, 1}, V{3, 3, 5}) == 1);  // entry y, t0y >= tmx
  REQUIRE(initialChildIndex(V{1, 1, 4}, V{5, 3, 5}) == 2);  // entry z, t0z >= tmy
  REQUIRE(initialChildIndex(V{2, 2, 2}, V{2, 2, 2}) == 6);  // tie: entry x, both others passed
}
