// Seed 001's PBRT v1 k-d builder (kinds/kd/pbrt_kd_builder.h) on hand trees, every node checked,
// and the strict OBJ reader (geometry/obj_exact.h) it is fed from.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include "geometry/obj_exact.h"
#include "kinds/kd/pbrt_kd_builder.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/voxel_faces.h"

namespace rtu {
namespace {

// Three triangles flat in x = 1 (y, z in [0, 1]) and two spanning x [0, 2] at y [3, 4].
std::vector<Aabb<float>> flatAndTwo() {
  std::vector<Aabb<float>> boxes;
  for (int i = 0; i < 3; ++i) boxes.push_back(Aabb<float>{{1, 0, 0}, {1, 1, 1}});
  for (int i = 0; i < 2; ++i) boxes.push_back(Aabb<float>{{0, 3, 0}, {2, 4, 1}});
  return boxes;
}

Aabb<float> box(float x0, float x1) {
  Aabb<float> b;
  b.grow({x0, 0, 0});
  b.grow({x1, 1, 1});
  return b;
}

TEST_CASE("PBRT k-d: the depth budget round(8 + 1.3 log2 N)", "[kd]") {
  CHECK(pbrtMaxDepth(3) == 10);     // 8 + 1.3 * 1.585 = 10.06
  CHECK(pbrtMaxDepth(200) == 18);   // 8 + 1.3 * 7.644 = 17.94 (R1's bunny)
  CHECK(pbrtMaxDepth(1023) == 21);  // 8 + 1.3 * 9.999 = 21.00 (R1's elephant)
  CHECK(pbrtMaxDepth(1368) == 22);  // 8 + 1.3 * 10.42 = 21.55 (spider)
}

// T0 = x [0, 1], T1 = [1, 2], T2 = [3, 4], all y, z [0, 1]. Root d = (4, 1, 1): axis x. Area
// 2 (4 + 4 + 1) = 18. Edges sorted: S0 0 | E0 1, S1 1 (END first) | E1 2 | S2 3 | E2 4.
// Candidates strictly inside (0, 4), cost 1 + 80 (A_b n_b + A_a n_a) / 18 with A = 2 (1 + 2 w):
//   E0 at 1: n_b 1, n_a 2, A_b 6, A_a 14: 1 + 80 (6 + 28) / 18 = 152.1
//   S1 at 1: n_b 1, n_a 2: the same cost, not strictly cheaper: E0 stays
//   E1 at 2: n_b 2, n_a 1, A_b = A_a = 10: 1 + 80 (20 + 10) / 18 = 134.3  <- best
//   S2 at 3: n_b 2, n_a 1, A_b 14, A_a 6: 1 + 80 (28 + 6) / 18 = 152.1
// 134.3 < 4 * 240: split at 2. Below: STARTs before E1 = S0, S1 -> [0, 1]; above: ENDs after E1 =
// E2 -> [2]. Both children hold <= 2: leaves. Nodes: 0 root, 1 below leaf, 2 above leaf.
TEST_CASE("PBRT k-d: three triangles, every node", "[kd]") {
  const KdBuild tree = buildPbrtKd({box(0, 1), box(1, 2), box(3, 4)}, PbrtKdParameters{});
  REQUIRE(tree.nodes.size() == 3);
  const KdBuildNode& root = tree.nodes[0];
  CHECK_FALSE(root.leaf);
  CHECK(root.axis == 0);
  CHECK(root.split == 2.0f);
  CHECK(root.above == 2);
  CHECK_FALSE(root.belowEmpty);
  CHECK_FALSE(root.aboveEmpty);
  CHECK(tree.nodes[1].leaf);
  CHECK(tree.nodes[1].listIndex == 0);
  CHECK(tree.nodes[1].count == 2);
  CHECK(tree.nodes[2].leaf);
  CHECK(tree.nodes[2].listIndex == 2);
  CHECK(tree.nodes[2].count == 1);
  CHECK(tree.lists == std::vector<uint32_t>{0, 1, 2});
  CHECK(tree.bounds.lower == glm::vec3(0, 0, 0));
  CHECK(tree.bounds.upper == glm::vec3(4, 1, 1));
  CHECK(tree.maxDepth == 10);
}

// Four triangles, T3 = [2.5, 3.5] added, with maxTriangles 1 so that the tree goes deeper. Costs
// are 1 + 80 (A_b n_b + A_a n_a) / A with A = 2 (1 + 2 w) for a side of width w (0.9 x 80 when a
// side is empty); the depth budget (10) never binds.
// Root (x [0, 4], A 18, oldCost 320): edges S0 0 | E0 1, S1 1 | E1 2 | S3 2.5 | S2 3 | E3 3.5 |
// E2 4.
//   E0, S1 at 1 (n_b 1, n_a 3): 6 + 42 -> 214.3;  E1 at 2 (2, 2): 20 + 20 -> 178.8  <- best;
//   S3 at 2.5 (2, 2): 24 + 16 -> 178.8, not strictly cheaper;  S2 at 3 (3, 2): 42 + 12 -> 241;
//   E3 at 3.5 (4, 1): 64 + 4 -> 303.2.  Below: STARTs before E1 = [0, 1]; above: ENDs after = [3,
//   2].
// Node 1 (x [0, 2], A 10, oldCost 160): E0 at 1 (1, 1): 6 + 6 -> 97 <- best (S1 at 1 the same).
//   Below [0] -> leaf 2; above [1] -> leaf 3.
// Node 4 (x [2, 4], A 10, oldCost 160): S3 at 2.5 (0, 2): 1 + 72 (8 x 2) / 10 = 116.2 <- best;
//   S2 at 3 (1, 2): 6 + 12 -> 145;  E3 at 3.5 (2, 1): 16 + 4 -> 161. Below empty -> leaf 5 (0
//   triangles); above: ENDs after S3 = [3, 2].
// Node 6 (x [2.5, 4], d (1.5, 1, 1), A 8): S2 at 3 (1, 2): 4 + 12 -> 161 <- best; E3 at 3.5 (2, 1):
//   12 + 4 -> 161, not cheaper. 161 > 160: a bad refine, but not > 4 x 160: split. Below [3] ->
//   leaf 7; above [3, 2].
// Node 8 (x [3, 4], d (1, 1, 1): z first, ties to the later axis): no z edge inside (0, 1); x: E3
//   at 3.5 (2, 1), A 6: 1 + 80 (8 + 4) / 6 = 161 > 160 (bad refine 2): split. Below: STARTs before
//   E3 = S3, S2 -> [3, 2] (node 9: no edge strictly inside on any axis -> a leaf of 2); above [2]
//   -> leaf 10.
TEST_CASE("PBRT k-d: four triangles, an empty child from the bonus, every node", "[kd]") {
  PbrtKdParameters parameters;
  parameters.maxTriangles = 1;
  const KdBuild tree = buildPbrtKd({box(0, 1), box(1, 2), box(3, 4), box(2.5f, 3.5f)}, parameters);
  REQUIRE(tree.nodes.size() == 11);
  struct Inner {
    uint32_t node;
    float split;
    uint32_t above;
    bool belowEmpty;
  };
  for (const Inner& inner : {Inner{0, 2, 4, false}, Inner{1, 1, 3, false}, Inner{4, 2.5f, 6, true},
                             Inner{6, 3, 8, false}, Inner{8, 3.5f, 10, false}}) {
    INFO("node " << inner.node);
    const KdBuildNode& node = tree.nodes[inner.node];
    CHECK_FALSE(node.leaf);
    CHECK(node.axis == 0);
    CHECK(node.split == inner.split);
    CHECK(node.above == inner.above);
    CHECK(node.belowEmpty == inner.belowEmpty);
    CHECK_FALSE(node.aboveEmpty);
  }
  struct Leaf {
    uint32_t node, listIndex, count;
  };
  for (const Leaf& leaf : {Leaf{2, 0, 1}, Leaf{3, 1, 1}, Leaf{5, 2, 0}, Leaf{7, 2, 1},
                           Leaf{9, 3, 2}, Leaf{10, 5, 1}}) {
    INFO("node " << leaf.node);
    CHECK(tree.nodes[leaf.node].leaf);
    CHECK(tree.nodes[leaf.node].listIndex == leaf.listIndex);
    CHECK(tree.nodes[leaf.node].count == leaf.count);
  }
  CHECK(tree.lists == std::vector<uint32_t>{0, 1, 3, 3, 2, 2});
}

// Three equal boxes: d = (1, 1, 1) picks z (ties to the later axis); no edge lies strictly inside
// on z, x or y, so after two retries the root stays a leaf of all three, over maxTriangles.
TEST_CASE("PBRT k-d: no candidate on any axis leaves a leaf", "[kd]") {
  const KdBuild tree = buildPbrtKd({box(0, 1), box(0, 1), box(0, 1)}, PbrtKdParameters{});
  REQUIRE(tree.nodes.size() == 1);
  CHECK(tree.nodes[0].leaf);
  CHECK(tree.nodes[0].count == 3);
  CHECK(tree.lists == std::vector<uint32_t>{0, 1, 2});
}

// Three triangles flat in x = 1 (y, z in [0, 1]) and two spanning x [0, 2] at y [3, 4]. The root
// (longest axis y, extent 4) splits at the flat ones' last END, y = 1 (cost 1 + 80 (3*10 + 2*22)/28
// = 212.4, the cheapest): below the flat three, above the other two (a leaf). The below node
// (x [0, 2], longest x) splits at x = 1 on the last END (cost 1: no triangle on either side, as
// R1's END-before-START order gives a triangle flat in the plane to neither child), so as R1 builds
// it both its children are empty leaves; pruned, it is an empty leaf its parent marks empty.
TEST_CASE("PBRT k-d: a node whose triangles lie flat in its split plane, as built and pruned",
          "[kd]") {
  const std::vector<Aabb<float>> boxes = flatAndTwo();
  PbrtKdParameters asR1;
  asR1.pruneEmptyPairs = false;
  const KdBuild built = buildPbrtKd(boxes, asR1);
  REQUIRE(built.nodes.size() == 5);
  CHECK(built.nodes[0].axis == 1);
  CHECK(built.nodes[0].split == 1.f);
  CHECK(built.nodes[0].above == 4);
  CHECK_FALSE(built.nodes[1].leaf);
  CHECK(built.nodes[1].axis == 0);
  CHECK(built.nodes[1].split == 1.f);
  CHECK(built.nodes[1].belowEmpty);
  CHECK(built.nodes[1].aboveEmpty);
  CHECK(built.nodes[2].count == 0);
  CHECK(built.nodes[3].count == 0);
  CHECK(built.prunedNodes == 0);

  const KdBuild pruned = buildPbrtKd(boxes, PbrtKdParameters{});
  REQUIRE(pruned.nodes.size() == 3);
  CHECK(pruned.prunedNodes == 1);
  CHECK(pruned.nodes[0].above == 2);
  CHECK(pruned.nodes[0].belowEmpty);
  CHECK_FALSE(pruned.nodes[0].aboveEmpty);
  CHECK(pruned.nodes[1].leaf);
  CHECK(pruned.nodes[1].count == 0);
  CHECK(pruned.nodes[2].leaf);
  CHECK(pruned.nodes[2].listIndex == 0);
  CHECK(pruned.nodes[2].count == 2);
  CHECK(pruned.lists == built.lists);
  CHECK(pruned.lists == std::vector<uint32_t>{3, 4});
}

// The same five boxes in PBRT's order (a START before an END at equal t). The root's y edges are
// S S S (0) | E E E (1) | S S (3) | E E (4): no START and END share a position, so the root splits
// as above, at the flat ones' last END (y = 1), below the flat three. The below node (x [0, 2],
// y [0, 1], z [0, 1], d = (2, 1, 1), area 10) now sorts S S S E E E at x = 1, every edge strictly
// inside; with A_b = A_a = 2 (1 + 1 * 2) = 6 each side is 0.6 of the node:
//   S (first): n_b 0, n_a 3, bonus: 1 + 80 * 0.9 * 0.6 * 3 = 130.6
//   S, S: n_b 1, 2 with n_a 3: 193, 241;  E, E, E: n_a 2, 1, 0 with n_b 3: 241, 193, 130.6
// The first START wins (the last END's equal cost is not strictly cheaper), 130.6 < 80 * 3: below
// it no START (an empty leaf), above it every END: the three flat triangles, kept. That node
// (x [1, 2], d = (1, 1, 1), axis z, then x, then y) has no edge strictly inside: a leaf of three.
TEST_CASE("PBRT k-d: PBRT's edge order keeps triangles flat in the split plane", "[kd]") {
  const std::vector<Aabb<float>> boxes = flatAndTwo();
  PbrtKdParameters pbrt;
  pbrt.edgeOrder = KdEdgeOrder::StartFirst;
  const KdBuild tree = buildPbrtKd(boxes, pbrt);
  REQUIRE(tree.nodes.size() == 5);
  CHECK(tree.nodes[0].axis == 1);
  CHECK(tree.nodes[0].split == 1.f);
  CHECK(tree.nodes[0].above == 4);
  CHECK(tree.nodes[1].axis == 0);
  CHECK(tree.nodes[1].split == 1.f);
  CHECK(tree.nodes[1].above == 3);
  CHECK(tree.nodes[1].belowEmpty);
  CHECK_FALSE(tree.nodes[1].aboveEmpty);
  CHECK(tree.nodes[2].leaf);
  CHECK(tree.nodes[2].count == 0);
  CHECK(tree.nodes[3].leaf);
  CHECK(tree.nodes[3].count == 3);
  CHECK(tree.nodes[4].count == 2);
  std::vector<uint32_t> listed = tree.lists;
  std::sort(listed.begin(), listed.end());
  CHECK(listed == std::vector<uint32_t>{0, 1, 2, 3, 4});
  CHECK(tree.prunedNodes == 0);
  CHECK(parseKdEdgeOrder("pbrt") == KdEdgeOrder::StartFirst);
  CHECK(parseKdEdgeOrder("r1") == KdEdgeOrder::EndFirst);
  CHECK_THROWS_WITH(parseKdEdgeOrder("pbrt2"), Catch::Contains("accel.kd_edge_order 'pbrt2'"));
}

// A voxel scene's faces all lie in planes where splits fall. In R1's order most are in no leaf's
// list (docs/triangles.md: 792 of the sphere's 6,288 at depth 5); in PBRT's every one is listed.
TEST_CASE("PBRT k-d: every voxel face is listed in PBRT's edge order", "[kd]") {
  const TriangleMesh faces = voxelFaces(*makeProceduralScene("sphere", 5));
  REQUIRE(faces.triangles.size() == 6288);
  std::vector<glm::dvec3> corners;
  for (const auto& triangle : faces.triangles)
    for (uint32_t v : triangle) corners.push_back(faces.vertices[v]);
  const auto listed = [&](KdEdgeOrder order) {
    PbrtKdParameters parameters;
    parameters.edgeOrder = order;
    const KdBuild tree = buildPbrtKd(pbrtTriangleBoxes(corners), parameters);
    return std::set<uint32_t>(tree.lists.begin(), tree.lists.end()).size();
  };
  CHECK(listed(KdEdgeOrder::StartFirst) == 6288);
  CHECK(listed(KdEdgeOrder::FlatKept) == 6288);
  CHECK(listed(KdEdgeOrder::EndFirst) == 792);
}

// With no triangle flat on an axis, FlatKept is R1's order: the hand tree of "three triangles,
// every node" (equal positions there: E0 and S1 at 1) comes out node for node. With the five boxes
// of the flat case, the flat three are kept: at x = 1 in the below node the order is S S S E E E
// (flat STARTs, then flat ENDs), as PBRT's, so the tree is the one derived for PBRT's order above.
TEST_CASE("PBRT k-d: FlatKept is R1's order but for flat triangles", "[kd]") {
  PbrtKdParameters flat;
  flat.edgeOrder = KdEdgeOrder::FlatKept;
  const std::vector<Aabb<float>> three = {box(0, 1), box(1, 2), box(3, 4)};
  const KdBuild r1 = buildPbrtKd(three, PbrtKdParameters{});
  const KdBuild kept = buildPbrtKd(three, flat);
  REQUIRE(kept.nodes.size() == r1.nodes.size());
  for (size_t i = 0; i < r1.nodes.size(); ++i) {
    CHECK(kept.nodes[i].split == r1.nodes[i].split);
    CHECK(kept.nodes[i].leaf == r1.nodes[i].leaf);
  }
  CHECK(kept.lists == r1.lists);
  const std::vector<Aabb<float>> boxes = flatAndTwo();
  const KdBuild tree = buildPbrtKd(boxes, flat);
  REQUIRE(tree.nodes.size() == 5);
  CHECK(tree.nodes[1].belowEmpty);
  CHECK(tree.nodes[3].count == 3);
  CHECK(tree.nodes[4].count == 2);
  CHECK(parseKdEdgeOrder("flat") == KdEdgeOrder::FlatKept);
}

TEST_CASE("strict OBJ: v, vn, f forms, quads split as (0,1,2), (2,3,0), errors by line", "[kd]") {
  const ObjMesh obj = parseObjExact(
      "# c\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0.1\nvn 0 0 1\nvt 0 0\nf 1//1 2//1 3//1 4//1\n"
      "f 1/1/1 2/1/1 4/1/1\nf 2 3 4\ns off\n",
      "m.obj");
  REQUIRE(obj.mesh.triangles.size() == 4);
  CHECK(obj.mesh.triangles[0] == std::array<uint32_t, 3>{0, 1, 2});
  CHECK(obj.mesh.triangles[1] == std::array<uint32_t, 3>{2, 3, 0});
  CHECK(obj.cornerNormals[2] == std::array<int32_t, 3>{0, 0, 0});
  CHECK(obj.cornerNormals[3] == std::array<int32_t, 3>{-1, -1, -1});
  CHECK(obj.mesh.vertices[3].z == 0.1);  // strtod: the double nearest 0.1
  CHECK_THROWS_WITH(parseObjExact("v 0 0 0\nf 1 2 3\n", "m.obj"),
                    Catch::Contains("m.obj:2") && Catch::Contains("'2'"));
  CHECK_THROWS_WITH(parseObjExact("v 0 0 x\n", "m.obj"), Catch::Contains("m.obj:1"));
  CHECK_THROWS_WITH(parseObjExact("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 1 2\n", "m.obj"),
                    Catch::Contains("3 or 4"));
}

}  // namespace
}  // namespace rtu
