// The binned and sweep SAH builders (kinds/bvh/sah_builder.h): a row of triangles whose tree is
// derived by hand, the leaf rule and the forced median, and properties on real meshes against the
// langr builder and the oracle.
#include <catch2/catch.hpp>

#include <numeric>

#include "bvh_meshes.h"
#include "kinds/bvh/bvh_image.h"
#include "kinds/bvh/bvh_quality.h"
#include "kinds/bvh/bvh_validator.h"
#include "kinds/bvh/langr_builder.h"
#include "kinds/bvh/sah_builder.h"

namespace rtu {
namespace {

SahBuilderConfig withSearch(SahSplitSearch search) {
  SahBuilderConfig config;
  config.search = search;
  return config;
}

struct Expected {
  uint32_t first, count, left, right;
};

}  // namespace

TEST_CASE("SAH builders: a row of 12 triangles, every node by hand", "[bvh][sah_builder]") {
  // Boxes of the triangles of centres a..b have area 2 (b - a + 1), so splitting n into k and
  // n - k costs 1 + (2k k + 2 (n-k)(n-k)) / (2n) against a leaf's n: the root (12 > 8 must
  // split) at 6 (cost 7); 6 at 3 (cost 4 < 6); 3 at 1 (2.67 < 3, the first of two equal); 2 stays
  // a leaf (split 2 = leaf 2). y and z: all centres equal, no split. Binned with 32 bins puts
  // every centre of these nodes in a bin of its own, so it finds the same splits.
  const std::vector<Expected> expected = {
      {0, 12, 1, 2},  {0, 6, 3, 4}, {6, 6, 9, 10}, {0, 3, 5, 6}, {3, 3, 7, 8},
      {0, 1, 0, 0},   {1, 2, 0, 0}, {3, 1, 0, 0},  {4, 2, 0, 0}, {6, 3, 11, 12},
      {9, 3, 13, 14}, {6, 1, 0, 0}, {7, 2, 0, 0},  {9, 1, 0, 0}, {10, 2, 0, 0}};
  const SahSplitSearch search = GENERATE(SahSplitSearch::Binned, SahSplitSearch::Sweep);
  const SahBuild build = buildSah(rowOfTriangles(12), withSearch(search));
  REQUIRE(build.tree.nodes.size() == expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    INFO("node " << i);
    CHECK(build.tree.nodes[i].first == expected[i].first);
    CHECK(build.tree.nodes[i].count == expected[i].count);
    CHECK(build.tree.nodes[i].left == expected[i].left);
    CHECK(build.tree.nodes[i].right == expected[i].right);
  }
  std::vector<uint32_t> inOrder(12);
  std::iota(inOrder.begin(), inOrder.end(), 0u);
  CHECK(build.tree.refs == inOrder);  // a row in order stays in order
  CHECK(build.tree.nodes[2].box.lower.x == 5.5);
  CHECK(build.forcedMedians == 0);
}

TEST_CASE("SAH builders: a leaf when splitting does not pay, unless it is too large",
          "[bvh][sah_builder]") {
  SahBuilderConfig config;
  config.costs = {100.0, 1.0};  // a box test dearer than all 12 triangle tests
  config.maxLeafSize = 16;
  CHECK(buildSah(rowOfTriangles(12), config).tree.nodes.size() == 1);
  config.maxLeafSize = 8;  // 12 triangles must split however dear: 6 and 6 then stay leaves
  const SahBuild forced = buildSah(rowOfTriangles(12), config);
  REQUIRE(forced.tree.nodes.size() == 3);
  CHECK(forced.tree.nodes[1].count == 6);
}

TEST_CASE("SAH builders: coincident centres are halved in order, counted", "[bvh][sah_builder]") {
  const SahSplitSearch search = GENERATE(SahSplitSearch::Binned, SahSplitSearch::Sweep);
  // 20 copies of one triangle: 20 -> 10 + 10 -> 5 + 5 each, leaves of 5 (at most 8).
  const SahBuild build = buildSah(rowOfTriangles(std::vector<double>(20, 3.0)), withSearch(search));
  CHECK(build.forcedMedians == 3);
  CHECK(build.tree.nodes.size() == 7);
  CHECK(build.tree.nodes[3].count == 5);
  CHECK(build.tree.nodes[6].first == 15);
}

TEST_CASE("SAH builders: refused settings", "[bvh][sah_builder]") {
  SahBuilderConfig config;
  config.bins = 1;
  CHECK_THROWS_WITH(buildSah(rowOfTriangles(4), config),
                    "binned builder: bins must be at least 2, not 1");
  config = {};
  config.maxLeafSize = 0;
  CHECK_THROWS_WITH(buildSah(rowOfTriangles(4), config),
                    "SAH builder: the maximum leaf size must be at least 1");
  CHECK_THROWS_WITH(buildSah(TriangleMesh{}), "binned builder: the mesh has no triangles");
}

TEST_CASE("SAH builders on real meshes: sound images, leaves of 1-8, SAH below langr's",
          "[bvh][sah_builder]") {
  const char* name = GENERATE("spider.obj", "WusonOBJ.obj");
  const TriangleMesh& mesh = assimpObjModel(name);
  const SahCosts unit{1.0, 1.0};
  const double langr = measureQuality(buildLangr(mesh).tree, unit).sah;
  double sah[2] = {0, 0};
  for (SahSplitSearch search : {SahSplitSearch::Binned, SahSplitSearch::Sweep}) {
    const SahBuild build = buildSah(mesh, withSearch(search));
    CHECK(validateBvh(layOut(build.tree, mesh).words).empty());
    for (const BuildNode& node : build.tree.nodes)
      if (node.leaf()) CHECK((node.count >= 1 && node.count <= 8));
    sah[search == SahSplitSearch::Sweep] = measureQuality(build.tree, unit).sah;
  }
  INFO(name << ": SAH langr " << langr << ", binned " << sah[0] << ", sweep " << sah[1]);
  CHECK(sah[0] < 0.9 * langr);
  CHECK(sah[1] <= 1.02 * sah[0]);
}

}  // namespace rtu

namespace rtu {

TEST_CASE("SAH builders: centres a subnormal apart are still binned", "[bvh][sah_builder]") {
  // Nine triangles in the planes x = t 2^-1070 (t = 0..8): the centres' extent 2^-1067 makes
  // bins / extent overflow to infinity; centre 0 is bin 0, the others the last bin, so the root
  // (9 > 8 triangles) splits 1 | 8 on x.
  TriangleMesh mesh;
  for (uint32_t t = 0; t < 9; ++t) {
    const double x = 0x1p-1070 * t;
    mesh.vertices.insert(mesh.vertices.end(), {{x, 0, 0}, {x, 1, 0}, {x, 0, 1}});
    mesh.triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  const SahBuild build = buildSah(mesh);
  REQUIRE(build.tree.nodes.size() >= 3);
  CHECK(build.tree.nodes[1].count == 1);
  CHECK(build.tree.nodes[2].count == 8);
  CHECK(build.forcedMedians == 0);
}

}  // namespace rtu
