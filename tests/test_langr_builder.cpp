// The langr builder (kinds/bvh/langr_builder.h), seed 003's Algorithms 3 and 4: splits, node
// numbering and reference order derived by hand on rows of triangles (bvh_meshes.h), the root
// rule, the forced median, and the tree's invariants on two real meshes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "bvh_meshes.h"
#include "kinds/bvh/langr_builder.h"

namespace rtu {
namespace {

Aabb<double> box(glm::dvec3 lower, glm::dvec3 upper) { return {lower, upper}; }

// The box of a row's triangles with centres a..b.
Aabb<double> rowBox(double a, double b) { return box({a - 0.5, 0, 0}, {b + 0.5, 1, 0}); }

void checkLeaf(const BuildNode& node, uint32_t first, uint32_t count) {
  CHECK(node.leaf());
  CHECK(node.first == first);
  CHECK(node.count == count);
}

void checkInner(const BuildNode& node, uint32_t left, uint32_t right) {
  CHECK_FALSE(node.leaf());
  CHECK(node.left == left);
  CHECK(node.right == right);
}

std::vector<uint32_t> sequence(uint32_t from, uint32_t to) {  // from..to, either direction
  std::vector<uint32_t> values;
  for (int64_t i = from;; i += from <= to ? 1 : -1) {
    values.push_back(static_cast<uint32_t>(i));
    if (i == to) break;
  }
  return values;
}

std::vector<uint32_t> concatenate(std::vector<uint32_t> a, const std::vector<uint32_t>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

// Centres in source order 5, 0, 11, 3, 8, 1, 10, 6, 2, 9, 4, 7. The centre box is [0, 11] on x
// (y and z are flat), so bin = floor(16 x / 11): x = 0..11 fall in bins 0, 1, 2, 4, 5, 7, 8, 10,
// 11, 13, 14 and 16, clamped to 15 (B1). Dividing after bin i puts k = (centres in bins <= i)
// on the left at SAH 2k·k + 2(12-k)(12-k) (a box over k adjacent centres has area 2k): k = 6
// only after bin 7 gives 144, the least (k = 5 or 7: 148). Left: x <= 5, in source order
// (triangles 0, 1, 3, 5, 8, 10); right: x >= 6 in reverse source order (11, 9, 7, 6, 4, 2).
TEST_CASE("langr: 12 triangles in a row split in the middle, the right part reversed", "[bvh]") {
  const LangrBuild build = buildLangr(rowOfTriangles({5, 0, 11, 3, 8, 1, 10, 6, 2, 9, 4, 7}));
  const BuildTree& tree = build.tree;
  REQUIRE(tree.nodes.size() == 3);
  checkInner(tree.nodes[0], 1, 2);
  checkLeaf(tree.nodes[1], 0, 6);
  checkLeaf(tree.nodes[2], 6, 6);
  CHECK(tree.nodes[0].box.lower == rowBox(0, 11).lower);
  CHECK(tree.nodes[0].box.upper == rowBox(0, 11).upper);
  CHECK(tree.nodes[1].box.upper == rowBox(0, 5).upper);
  CHECK(tree.nodes[1].box.lower == rowBox(0, 5).lower);
  CHECK(tree.nodes[2].box.lower == rowBox(6, 11).lower);
  CHECK(tree.nodes[2].box.upper == rowBox(6, 11).upper);
  CHECK(tree.refs == std::vector<uint32_t>{0, 1, 3, 5, 8, 10, 11, 9, 7, 6, 4, 2});
  CHECK(build.forcedMedians == 0);
  CHECK(build.maxPendingNodes == 0);
}

TEST_CASE("langr: the root is a leaf below 10 triangles, a child up to 10 (B4)", "[bvh]") {
  SECTION("9: one leaf") {
    const BuildTree tree = buildLangr(rowOfTriangles(9)).tree;
    REQUIRE(tree.nodes.size() == 1);
    checkLeaf(tree.nodes[0], 0, 9);
    CHECK(tree.nodes[0].box.lower == rowBox(0, 8).lower);
    CHECK(tree.nodes[0].box.upper == rowBox(0, 8).upper);
    CHECK(tree.refs == sequence(0, 8));
  }
  // Bins floor(16 x / 9): x = 0..9 in 0, 1, 3, 5, 7, 8, 10, 12, 14, 15. k = 5 (after bin 7):
  // SAH 2·25 + 2·25 = 100, less than k = 4 or 6 (104).
  SECTION("10: split 5 + 5, both leaves") {
    const BuildTree tree = buildLangr(rowOfTriangles(10)).tree;
    REQUIRE(tree.nodes.size() == 3);
    checkInner(tree.nodes[0], 1, 2);
    checkLeaf(tree.nodes[1], 0, 5);
    checkLeaf(tree.nodes[2], 5, 5);
    CHECK(tree.refs == concatenate(sequence(0, 4), sequence(9, 5)));
  }
  // Bins floor(16 x / 10): x = 0..10 in 0, 1, 3, 4, 6, 8, 9, 11, 12, 14, 15. k = 5 (after bins 6
  // and 7) and k = 6 (after bin 8) both cost 2·25 + 2·36 = 122: the first minimum wins.
  SECTION("11: split 5 + 6 at the first of two equal minima") {
    const BuildTree tree = buildLangr(rowOfTriangles(11)).tree;
    REQUIRE(tree.nodes.size() == 3);
    checkLeaf(tree.nodes[1], 0, 5);
    checkLeaf(tree.nodes[2], 5, 6);
    CHECK(tree.refs == concatenate(sequence(0, 4), sequence(10, 5)));
  }
}

// 22 copies of one triangle: every centre box is a point, so each split halves the references in
// their order (B2). The root's halves (11 each) both split again; the left one first, so its
// children are nodes 3, 4 and the right one's, taken from the stack, 5, 6.
TEST_CASE("langr: coinciding centres split at the median, depth first, left first", "[bvh]") {
  const LangrBuild build = buildLangr(rowOfTriangles(std::vector<double>(22, 0.0)));
  const BuildTree& tree = build.tree;
  CHECK(build.forcedMedians == 3);
  CHECK(build.maxPendingNodes == 1);
  REQUIRE(tree.nodes.size() == 7);
  checkInner(tree.nodes[0], 1, 2);
  checkInner(tree.nodes[1], 3, 4);
  checkInner(tree.nodes[2], 5, 6);
  checkLeaf(tree.nodes[3], 0, 5);
  checkLeaf(tree.nodes[4], 5, 6);
  checkLeaf(tree.nodes[5], 11, 5);
  checkLeaf(tree.nodes[6], 16, 6);
  CHECK(tree.refs == sequence(0, 21));
  for (const BuildNode& node : tree.nodes) {
    CHECK(node.box.lower == rowBox(0, 0).lower);
    CHECK(node.box.upper == rowBox(0, 0).upper);
  }
}

TEST_CASE("langr: meshes and settings it cannot build are refused", "[bvh]") {
  CHECK_THROWS_WITH(buildLangr(TriangleMesh{}), Catch::Contains("no triangles"));
  TriangleMesh mesh = rowOfTriangles(3);
  LangrConfig config;
  config.bins = 1;
  CHECK_THROWS_WITH(buildLangr(mesh, config), Catch::Contains("bins must be at least 2"));
  config = {};
  config.leafThreshold = 0;
  CHECK_THROWS_WITH(buildLangr(mesh, config), Catch::Contains("leaf threshold"));
  mesh.triangles[2][1] = 9;
  CHECK_THROWS_WITH(buildLangr(mesh), Catch::Contains("triangle 2 names vertex 9 of 9"));
  mesh = rowOfTriangles(3);
  mesh.vertices[4].y = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(buildLangr(mesh), std::invalid_argument);
}

// Invariants on real meshes: the references are a permutation, each inner node's children are
// its range split in two, every box encloses its children's or its triangles' boxes, leaves hold
// 1 to 10 triangles, and the same input gives the same tree.
TEST_CASE("langr: tree invariants on spider and Wuson", "[bvh]") {
  const std::string name = GENERATE(as<std::string>{}, "spider.obj", "WusonOBJ.obj");
  INFO(name);
  const TriangleMesh& mesh = assimpObjModel(name);
  const BuildTree tree = buildLangr(mesh).tree;
  std::vector<uint32_t> sorted = tree.refs;
  std::sort(sorted.begin(), sorted.end());
  CHECK(sorted == sequence(0, static_cast<uint32_t>(mesh.triangles.size() - 1)));
  size_t leaves = 0;
  for (const BuildNode& node : tree.nodes) {
    if (node.leaf()) {
      ++leaves;
      CHECK(node.count >= 1);
      CHECK(node.count <= 10);
      for (uint32_t i = node.first; i < node.first + node.count; ++i)
        for (uint32_t vertex : mesh.triangles[tree.refs[i]])
          CHECK(node.box.contains(Aabb<double>{mesh.vertices[vertex], mesh.vertices[vertex]}));
      continue;
    }
    const BuildNode& left = tree.nodes[node.left];
    const BuildNode& right = tree.nodes[node.right];
    CHECK(node.right == node.left + 1);
    CHECK(left.first == node.first);
    CHECK(right.first == left.first + left.count);
    CHECK(left.count + right.count == node.count);
    CHECK(node.box.contains(left.box));
    CHECK(node.box.contains(right.box));
  }
  CHECK(tree.nodes.size() == 2 * leaves - 1);
  const BuildTree again = buildLangr(mesh).tree;
  CHECK(again.refs == tree.refs);
  CHECK(std::equal(again.nodes.begin(), again.nodes.end(), tree.nodes.begin(), tree.nodes.end(),
                   [](const BuildNode& a, const BuildNode& b) {
                     return a.box.lower == b.box.lower && a.box.upper == b.box.upper &&
                            a.first == b.first && a.count == b.count && a.left == b.left &&
                            a.right == b.right;
                   }));
}

}  // namespace rtu
