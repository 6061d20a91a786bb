// The builders' primitive entry points (kinds/bvh/build_primitives.h): boxes alone build the same
// trees as the mesh entry points over the same boxes, and what checkPrimitives refuses.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "bvh_meshes.h"
#include "kinds/bvh/langr_builder.h"
#include "kinds/bvh/lbvh_builder.h"
#include "kinds/bvh/sah_builder.h"

namespace rtu {
namespace {

BuildPrimitives boxesOf(const TriangleMesh& mesh) {
  return boxPrimitives(buildPrimitives(mesh, "test").boxes);
}

bool sameTree(const BuildTree& a, const BuildTree& b) {
  if (a.refs != b.refs || a.nodes.size() != b.nodes.size()) return false;
  for (size_t i = 0; i < a.nodes.size(); ++i) {
    const BuildNode &x = a.nodes[i], &y = b.nodes[i];
    if (x.first != y.first || x.count != y.count || x.left != y.left || x.right != y.right ||
        x.box.lower != y.box.lower || x.box.upper != y.box.upper)
      return false;
  }
  return true;
}

Aabb<double> box(glm::dvec3 lower, glm::dvec3 upper) {
  Aabb<double> b;
  b.lower = lower;
  b.upper = upper;
  return b;
}

}  // namespace

TEST_CASE("Builders over boxes build what they build over a mesh's triangles", "[bvh]") {
  const TriangleMesh& mesh = assimpObjModel("spider.obj");
  const BuildPrimitives boxes = boxesOf(mesh);
  CHECK(sameTree(buildSah(boxes).tree, buildSah(mesh).tree));
  CHECK(sameTree(buildLangr(boxes).tree, buildLangr(mesh).tree));
  CHECK(sameTree(buildLbvh(boxes).tree, buildLbvh(mesh).tree));
}

TEST_CASE("Builders over boxes: a single box at leaf size 1 is a root leaf", "[bvh]") {
  const BuildPrimitives one = boxPrimitives({box({0, 0, 0}, {1, 2, 3})});
  CHECK(one.centres[0] == glm::dvec3(0.5, 1, 1.5));
  SahBuilderConfig sah;
  sah.maxLeafSize = 1;
  LangrConfig langr;
  langr.leafThreshold = 1;
  for (const BuildTree& tree : {buildSah(one, sah).tree, buildLangr(one, langr).tree}) {
    REQUIRE(tree.nodes.size() == 1);
    CHECK(tree.nodes[0].leaf());
    CHECK(tree.nodes[0].count == 1);
  }
}

TEST_CASE("checkPrimitives refuses what no builder can build over", "[bvh]") {
  CHECK_THROWS_AS(buildSah(BuildPrimitives{}), std::invalid_argument);
  CHECK_THROWS_AS(buildLangr(boxPrimitives({Aabb<double>{}})), std::invalid_argument);  // empty
  CHECK_THROWS_AS(buildLbvh(boxPrimitives({box({0, 0, 0}, {NAN, 1, 1})})), std::invalid_argument);
  BuildPrimitives mismatched = boxPrimitives({box({0, 0, 0}, {1, 1, 1})});
  mismatched.centres.clear();
  CHECK_THROWS_AS(buildSah(mismatched), std::invalid_argument);
}

}  // namespace rtu
