// The BIH builder (kinds/bih/bih_builder.h) on the hand scene of bih_hand_scene.h, every node and
// clip plane derived by hand below, and its properties on spider.obj.
#include <catch2/catch.hpp>

#include <set>

#include "bih_hand_scene.h"
#include "bvh_meshes.h"
#include "geometry/ray_sets.h"
#include "kinds/bih/bih_builder.h"

namespace rtu {
namespace {

struct HandBuild {
  SceneGrid grid{meshBounds(bihHandMesh()), kFourBitC99};
  ProjectedMesh projected = projectMesh(bihHandMesh(), grid);
  std::vector<GridBox> boxes = triangleBoxes(bihHandMesh(), grid, projected);
};

void checkInner(const BihBuildNode& node, uint32_t axis, int64_t clip0, int64_t clip1,
                uint32_t child) {
  CHECK_FALSE(node.leaf);
  CHECK(node.axis == axis);
  CHECK(node.clip0 == clip0);
  CHECK(node.clip1 == clip1);
  CHECK(node.index == child);
}

void checkLeaf(const BihBuildNode& node, uint32_t first, uint32_t count) {
  CHECK(node.leaf);
  CHECK(node.index == first);
  CHECK(node.count == count);
}

}  // namespace

TEST_CASE("BIH builder: the hand scene's boxes and grid", "[bih]") {
  const HandBuild hand;
  CHECK(hand.grid.scale() == 1.0);  // the box's longest side, x, spans 15 = 2^4 - 1
  CHECK(sceneUpper(hand.grid) == GridPoint{15, 7, 3});
  REQUIRE(hand.boxes.size() == 4);
  CHECK(hand.boxes[1].lower == GridPoint{2, 0, 2});
  CHECK(hand.boxes[1].upper == GridPoint{9, 7, 2});
  CHECK(hand.boxes[3].lower == GridPoint{12, 3, 3});
  CHECK(hand.boxes[3].upper == GridPoint{15, 6, 3});
}

TEST_CASE("BIH builder: the hand scene with leaves of one triangle, node by node", "[bih]") {
  const HandBuild hand;
  const BihBuild build = buildBih(hand.boxes, sceneUpper(hand.grid), BihBuildSettings{1});
  // Half-grid candidates (sums lower + upper). Root: x [0, 30], y [0, 14], z [0, 6]; x longest,
  // middle 15: T0 (6), T1 (11) left, T2 (26), T3 (27) right. clip0 = max(6, 9) = 9, clip1 =
  // min(11, 12) = 11; children 1, 2.
  // Node 1 (T0, T1): x [0, 15], y [0, 14]: x, middle 7: T0 (6) left, T1 (11) right; clip0 = 6,
  // clip1 = 2 (they overlap); children 3, 4.
  // Node 2 (T2, T3): x [16, 30] and y [0, 14] tie at 14, x taken; middle 23 puts both right, so
  // no node: x shrinks to [24, 30]. Now y is longest, middle 7: T2 (4) left, T3 (9) right;
  // clip0 = T2's upper 4, clip1 = T3's lower 3; children 5, 6.
  // Leaves 3-6 are T0-T3, listed in that order (node 1's subtree is built before node 2's).
  REQUIRE(build.nodes.size() == 7);
  checkInner(build.nodes[0], 0, 9, 11, 1);
  checkInner(build.nodes[1], 0, 6, 2, 3);
  checkInner(build.nodes[2], 1, 4, 3, 5);
  for (uint32_t t = 0; t < 4; ++t) checkLeaf(build.nodes[3 + t], t, 1);
  CHECK(build.list == std::vector<uint32_t>{0, 1, 2, 3});
  CHECK(build.depth == 2);
}

TEST_CASE("BIH builder: leaves of up to 4 (the default) make the hand scene one leaf", "[bih]") {
  const HandBuild hand;
  const BihBuild build = buildBih(hand.boxes, sceneUpper(hand.grid));
  REQUIRE(build.nodes.size() == 1);
  checkLeaf(build.nodes[0], 0, 4);
  CHECK(build.depth == 0);
}

TEST_CASE("BIH builder: equal centres end in one leaf, however many", "[bih]") {
  // Five boxes with the same centre: every split puts them on one side, so the candidate halves,
  // axis after axis, without a node, until its longest side is under a grid unit (2 half units).
  const std::vector<GridBox> boxes(5, GridBox{{6, 0, 0}, {9, 1, 1}});
  const BihBuild build = buildBih(boxes, {15, 15, 15}, BihBuildSettings{1});
  REQUIRE(build.nodes.size() == 1);
  checkLeaf(build.nodes[0], 0, 5);
}

TEST_CASE("BIH builder: no triangles or a leaf size of 0 are refused", "[bih]") {
  CHECK_THROWS_WITH(buildBih({}, {1, 1, 1}), Catch::Contains("no triangles"));
  const std::vector<GridBox> one(1);
  CHECK_THROWS_WITH(buildBih(one, {1, 1, 1}, BihBuildSettings{0}), Catch::Contains("leaf size"));
}

TEST_CASE("BIH builder: properties on spider", "[bih]") {
  const TriangleMesh& mesh = assimpObjModel("spider.obj");
  const SceneGrid grid(meshBounds(mesh), kC99Format);
  const ProjectedMesh projected = projectMesh(mesh, grid);
  const std::vector<GridBox> boxes = triangleBoxes(mesh, grid, projected);
  const BihBuild build = buildBih(boxes, sceneUpper(grid));
  CHECK(build.depth <= kBihMaxDepth);
  std::multiset<uint32_t> listed(build.list.begin(), build.list.end());
  for (uint32_t t = 0; t < boxes.size(); ++t) CHECK(listed.count(t) == 1);
  CHECK(build.list.size() == boxes.size());
  uint32_t leaves = 0;
  for (const BihBuildNode& node : build.nodes) {
    if (!node.leaf) continue;
    ++leaves;
    CHECK(node.count >= 1);
    CHECK(node.count <= 4);  // spider has no 5 triangles with centres under a unit apart
  }
  CHECK(build.nodes.size() == 2 * leaves - 1);  // every inner node has two children
  INFO("nodes " << build.nodes.size() << ", leaves " << leaves << ", depth " << build.depth);
  CHECK(build.nodes.size() < 1312);
}

}  // namespace rtu
