// The two-level BVH (kinds/bvh/two_level.h, top_level_walk.h, two_level_traversal.h) on a hand
// scene: three instances of a unit square, their world boxes, the top level's tree, and which
// instance and triangle each ray hits at which t, all derived by hand below; the per-frame
// rebuild keeps the mesh images.
//
// The mesh: the square [0, 1]^2 at z = 0 as triangle 0 (0,0,0), (1,0,0), (0,1,0) and triangle 1
// (1,0,0), (1,1,0), (0,1,0). Its image's root box is [0, 1] x [0, 1] x [0, 0]. The instances
// (rotations with entries 0 and ±1, scales and translations powers of two, so every float32
// transform and model-space ray below is exact):
//   I0  translation (0, 0, 5)                           world box [0, 1] x [0, 1] x [5, 5]
//   I1  R = Rx(90°): (x, y, z) -> (x, -z, y); T (4, 0, 0)  box [4, 5] x [0, 0] x [0, 1]
//   I2  S = 2, R = Rz(90°): (x, y) -> (-y, x); T (1, 0, 0) box [-1, 1] x [0, 2] x [0, 0]
// Top level (binned, leaves of 1; SAH costs as 1 + (A_l n_l + A_r n_r) / A_node). Areas: I0 2,
// I1 2, I2 8; {I0, I2} 48, {I1, I2} 40, {I0, I1} 70; the root [-1, 5] x [0, 2] x [0, 5] 104.
// x (centres 0.5, 4.5, 0 in 4 bins of 4.5 / 4): {I2, I0} | {I1} = 96 + 2 = 98. y (centres 0.5, 0,
// 1): {I1} | {I0, I2} = 2 + 96 = 98, not below x's. z (centres 5, 0.5, 0): {I1, I2} | {I0} = 80 +
// 2 = 82: the split, the left keeping reference order (I1, I2). Node 1 = {I1, I2} divides on x:
// I2 (centre 0) left, I1 (4.5) right. So: root (children 1, 2); node 1 (children 3, 4); node 2
// leaf I0; node 3 leaf I2; node 4 leaf I1; references [2, 1, 0].
#include <catch2/catch.hpp>

#include <cmath>

#include "kinds/bvh/langr_builder.h"
#include "kinds/bvh/two_level_traversal.h"

namespace rtu {
namespace {

TriangleMesh unitSquare() {
  TriangleMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {1, 3, 2}};
  return mesh;
}

ModelPlacement placement(glm::dvec3 translation, glm::dmat3 rotation = glm::dmat3(1.0),
                         double scale = 1.0) {
  return ModelPlacement{translation, rotation, glm::dvec3(scale)};
}

// glm's matrices are column-major: each argument triple is a column, the image of an axis.
const glm::dmat3 kRx90(1, 0, 0, 0, 0, 1, 0, -1, 0);  // y -> z, z -> -y
const glm::dmat3 kRz90(0, 1, 0, -1, 0, 0, 0, 0, 1);  // x -> y, y -> -x

std::vector<BvhInstance> handInstances() {
  return {{0, placement({0, 0, 5})},
          {0, placement({4, 0, 0}, kRx90)},
          {0, placement({1, 0, 0}, kRz90, 2.0)}};
}

TwoLevelBvh handScene(const TopLevelConfig& config = {}) {
  const TriangleMesh mesh = unitSquare();
  std::vector<MeshBvh> meshes;
  meshes.push_back(meshBvh(buildLangr(mesh).tree, mesh));
  TwoLevelBvh bvh(std::move(meshes), config);
  bvh.place(handInstances());
  return bvh;
}

RayRecord ray(glm::vec3 origin, glm::vec3 direction) {
  return RayRecord{0, {origin.x, origin.y, origin.z}, {direction.x, direction.y, direction.z}, 0};
}

void checkBox(const Aabb<double>& box, glm::dvec3 lower, glm::dvec3 upper) {
  CHECK(box.lower == lower);
  CHECK(box.upper == upper);
}

}  // namespace

TEST_CASE("Two-level BVH: instance world boxes and the top level's tree, by hand", "[two_level]") {
  const TwoLevelBvh bvh = handScene();
  const TopLevel& top = bvh.topLevel();
  REQUIRE(top.worldBoxes.size() == 3);
  checkBox(top.worldBoxes[0], {0, 0, 5}, {1, 1, 5});
  checkBox(top.worldBoxes[1], {4, 0, 0}, {5, 0, 1});
  checkBox(top.worldBoxes[2], {-1, 0, 0}, {1, 2, 0});
  // A rotation by 30° about z: the square's corners (0,0), (1,0), (0,1), (1,1) go to (0,0),
  // (c, s), (-s, c), (c - s, s + c), so the box is [-s, c] x [0, s + c] (c = cos 30°, s = 1/2).
  const Aabb<double> turned = placedBox(bvh.meshes()[0].rootBox,
                                        placement({0, 0, 0}, rotationFromEulerDegrees({0, 0, 30})));
  CHECK(turned.lower.x == Approx(-0.5));
  CHECK(turned.upper.x == Approx(std::sqrt(3.0) / 2));
  CHECK(turned.upper.y == Approx(0.5 + std::sqrt(3.0) / 2));
  REQUIRE(top.tree.nodes.size() == 5);
  CHECK(top.tree.nodes[0].left == 1);
  CHECK(top.tree.nodes[1].left == 3);
  CHECK(top.tree.nodes[2].leaf());
  CHECK(top.tree.nodes[3].leaf());
  CHECK(top.tree.nodes[4].leaf());
  CHECK(top.tree.refs == std::vector<uint32_t>{2, 1, 0});
  const BvhImageView image(top.image.words);
  CHECK(image.header().nodeCount == 5);
  CHECK(image.header().listCount == 3);
  CHECK(image.header().triangleCount == 0);
  CHECK(image.node(2).box.lower == glm::vec3(0, 0, 5));  // I0's box, exact in float32
}

TEST_CASE("Two-level BVH: the nearest instance, its triangle and t, by hand", "[two_level]") {
  const TwoLevelBvh bvh = handScene();
  TwoLevelTraversal<WatertightIntersector> traversal(bvh);
  SECTION("down at (1/4, 1/4): I0 at t = 5 before I2 at 10") {
    // Root hit. Node 1 ({I1, I2}, z in [0, 1]) enters at t = 9, node 2 (I0, z = 5) at 5: node 2
    // first, node 1 pushed. I0: the model ray from (1/4, 1/4, 5) down meets triangle 0 at t = 5,
    // u = v = 1/4. The popped node 1 begins at 9 > 5: skipped.
    const TwoLevelResult hit = traversal.trace(ray({0.25f, 0.25f, 10}, {0, 0, -1}), 0, INFINITY);
    CHECK(hit.hit);
    CHECK(hit.instance == 0);
    CHECK(hit.primitive == 0);
    CHECK(hit.t == 5.0f);
    CHECK(hit.u == 0.25f);
    CHECK(hit.v == 0.25f);
    CHECK(hit.counts.top.nodes == 3);
    CHECK(hit.counts.top.boxTests == 3);
    CHECK(hit.counts.top.pushes == 1);
    CHECK(hit.counts.top.pops == 1);
    CHECK(hit.counts.top.instances == 1);
    CHECK(hit.counts.mesh.triangleTests > 0);
  }
  SECTION("down at (1/2, 5/4): past I0's box, I2 at t = 10") {
    // Node 2 (I0, y <= 1) missed; node 1, then node 3 (I2) hit and node 4 (I1, x >= 4) missed.
    // I2's model ray: ((1/2, 5/4) - (1, 0)) turned back by Rz(-90°), (x, y) -> (y, -x), and halved:
    // (5/8, 1/4, 5) with direction (0, 0, -1/2): t = 10 at triangle 0, u = 5/8, v = 1/4.
    const TwoLevelResult hit = traversal.trace(ray({0.5f, 1.25f, 10}, {0, 0, -1}), 0, INFINITY);
    CHECK(hit.instance == 2);
    CHECK(hit.primitive == 0);
    CHECK(hit.t == 10.0f);
    CHECK(hit.u == 0.625f);
    CHECK(hit.v == 0.25f);
    CHECK(hit.counts.top.nodes == 5);
    CHECK(hit.counts.top.boxTests == 5);
    CHECK(hit.counts.top.pushes == 0);
    CHECK(hit.counts.top.instances == 1);
  }
  SECTION("along +y at (9/2, -5, 1/4): the upright I1 at t = 5") {
    // I1's model ray: (1/2, -5, 1/4) turned back, (x, y, z) -> (x, z, -y): (1/2, 1/4, 5) going
    // (0, 0, -1): triangle 0 at t = 5, u = 1/2, v = 1/4.
    const TwoLevelResult hit = traversal.trace(ray({4.5f, -5, 0.25f}, {0, 1, 0}), 0, INFINITY);
    CHECK(hit.instance == 1);
    CHECK(hit.primitive == 0);
    CHECK(hit.t == 5.0f);
    CHECK(hit.u == 0.5f);
    CHECK(hit.v == 0.25f);
  }
  SECTION("a ray past the root's box: one box test, no mesh traced") {
    const TwoLevelResult miss = traversal.trace(ray({10, 10, 10}, {0, 0, 1}), 0, INFINITY);
    CHECK_FALSE(miss.hit);
    CHECK(miss.counts.top.nodes == 1);
    CHECK(miss.counts.top.boxTests == 1);
    CHECK(miss.counts.top.instances == 0);
    CHECK(miss.counts.meshCost == 0);
  }
  SECTION("t_max before every instance: no hit") {
    CHECK_FALSE(traversal.trace(ray({0.25f, 0.25f, 10}, {0, 0, -1}), 0, 4.0f).hit);
  }
}

TEST_CASE("Two-level BVH: a top leaf of all three instances gives the same hits", "[two_level]") {
  // langr at leaf threshold 4: a root of 3 is a leaf (3 < 4, B4). (Binned at leaf size 3 still
  // splits: its root's split costs 1 + 82/104 against a leaf's 3.)
  TopLevelConfig config;
  config.builder = TopLevelBuilder::Langr;
  config.leafSize = 4;
  const TwoLevelBvh bvh = handScene(config);
  REQUIRE(bvh.topLevel().tree.nodes.size() == 1);
  TwoLevelTraversal<WatertightIntersector> traversal(bvh);
  // Every instance of the root leaf is traced: I0 hits at 5, then I1 and I2 with t_max = 5 do not.
  const TwoLevelResult hit = traversal.trace(ray({0.25f, 0.25f, 10}, {0, 0, -1}), 0, INFINITY);
  CHECK(hit.instance == 0);
  CHECK(hit.t == 5.0f);
  CHECK(hit.counts.top.instances == 3);
}

TEST_CASE("Two-level BVH: a new frame rebuilds the top level, not the meshes", "[two_level]") {
  TwoLevelBvh bvh = handScene();
  TwoLevelTraversal<WatertightIntersector> traversal(bvh);
  const uint32_t* meshWords = bvh.meshes()[0].image.words.data();
  const std::vector<uint32_t> meshImage = bvh.meshes()[0].image.words;
  std::vector<BvhInstance> moved = handInstances();
  moved[0].placement.translation = {0, 0, -5};  // I0 now below I2
  bvh.place(moved);
  CHECK(bvh.meshes()[0].image.words.data() == meshWords);  // the same image, not rebuilt
  CHECK(bvh.meshes()[0].image.words == meshImage);
  checkBox(bvh.topLevel().worldBoxes[0], {0, 0, -5}, {1, 1, -5});
  // Down at (1/4, 1/4): I2 at z = 0 now comes first, t = 10. Its model ray: ((1/4, 1/4) - (1, 0))
  // -> (1/4, 3/4) halved: (1/8, 3/8): triangle 0, u = 1/8, v = 3/8.
  const TwoLevelResult hit = traversal.trace(ray({0.25f, 0.25f, 10}, {0, 0, -1}), 0, INFINITY);
  CHECK(hit.instance == 2);
  CHECK(hit.t == 10.0f);
  CHECK(hit.u == 0.125f);
  CHECK(hit.v == 0.375f);
}

TEST_CASE("Two-level BVH refuses what it cannot place", "[two_level]") {
  CHECK_THROWS_AS(TwoLevelBvh({}), std::invalid_argument);
  TwoLevelBvh bvh = handScene();
  CHECK_THROWS_AS(bvh.place({}), std::invalid_argument);
  CHECK_THROWS_WITH(bvh.place({{1, placement({0, 0, 0})}}),
                    Catch::Contains("instance 0 names mesh 1 of 1"));
  CHECK_THROWS_WITH(bvh.place({{0, placement({0, 0, 0})}, {0, placement({0, 0, 0}, {}, 0.0)}}),
                    Catch::Contains("instance 1"));
}

}  // namespace rtu
