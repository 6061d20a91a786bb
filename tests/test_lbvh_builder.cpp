// The linear BVH builder (kinds/bvh/lbvh_builder.h): Morton codes by hand, a row of triangles
// divided at the codes' highest differing bits, equal codes halved, and real meshes.
#include <catch2/catch.hpp>

#include "bvh_meshes.h"
#include "kinds/bvh/bvh_image.h"
#include "kinds/bvh/bvh_quality.h"
#include "kinds/bvh/bvh_validator.h"
#include "kinds/bvh/lbvh_builder.h"
#include "kinds/bvh/sah_builder.h"

namespace rtu {

TEST_CASE("LBVH: Morton codes interleave x, y, z from the top", "[bvh][lbvh]") {
  CHECK(mortonCode(1, 0, 0) == 4);
  CHECK(mortonCode(0, 1, 0) == 2);
  CHECK(mortonCode(0, 0, 1) == 1);
  CHECK(mortonCode(2, 0, 0) == 32);
  CHECK(mortonCode(512, 0, 0) == 1u << 29);
  CHECK(mortonCode(0, 0, 512) == 1u << 27);
  CHECK(mortonCode(1023, 1023, 1023) == 0x3fffffffu);
  CHECK(mortonCode(1024, 0, 0) == 0);  // only 10 bits
}

TEST_CASE("LBVH: a row divided at the highest differing bit", "[bvh][lbvh]") {
  // Centres x = 0..11 fall in cells floor(1024 x / 11): 0, 93, 186, 279, 372, 465, 558, 651, 744,
  // 837, 930, 1023 (y and z have no extent: cell 0). The root's codes differ first in x's bit 9
  // (cell 512): 6 | 6. Cells 0..465 differ first at 256: 3 | 3; cells 558..1023 (558 ^ 1023 =
  // 0b0111010001) at 256 within 512, that is from 768: 3 | 3. Nodes of at most 4 are leaves.
  const LbvhBuild build = buildLbvh(rowOfTriangles(12));
  const auto& nodes = build.tree.nodes;
  REQUIRE(nodes.size() == 7);
  CHECK((nodes[0].left == 1 && nodes[0].right == 2));
  CHECK((nodes[1].count == 6 && nodes[2].first == 6));
  CHECK((nodes[1].left == 3 && nodes[2].left == 5));
  for (uint32_t i = 3; i < 7; ++i) CHECK((nodes[i].leaf() && nodes[i].count == 3));
  CHECK(build.equalCodeSplits == 0);
  SECTION("leaves of one: cells 0, 93, 186 divide at 128 (2 | 1), then 0, 93 at 64") {
    LbvhConfig single;
    single.maxLeafSize = 1;
    const LbvhBuild fine = buildLbvh(rowOfTriangles(12), single);
    CHECK(fine.tree.nodes.size() == 23);
    CHECK(fine.tree.nodes[3].count == 3);  // triangles 0..2
    CHECK(fine.tree.nodes[fine.tree.nodes[3].left].count == 2);
  }
}

TEST_CASE("LBVH: equal codes are halved, counted", "[bvh][lbvh]") {
  // 20 -> 10 + 10 -> 5 + 5 each -> 2 + 3 each: leaves of at most 4.
  const LbvhBuild build = buildLbvh(rowOfTriangles(std::vector<double>(20, 1.0)));
  CHECK(build.equalCodeSplits == 7);
  CHECK(build.tree.nodes.size() == 15);
}

TEST_CASE("LBVH on real meshes: sound images, leaves of at most 4, SAH above binned",
          "[bvh][lbvh]") {
  const char* name = GENERATE("spider.obj", "WusonOBJ.obj");
  const TriangleMesh& mesh = assimpObjModel(name);
  const LbvhBuild build = buildLbvh(mesh);
  CHECK(validateBvh(layOut(build.tree, mesh).words).empty());
  for (const BuildNode& node : build.tree.nodes)
    if (node.leaf()) CHECK((node.count >= 1 && node.count <= 4));
  const SahCosts unit{1.0, 1.0};
  const double lbvh = measureQuality(build.tree, unit).sah;
  const double binned = measureQuality(buildSah(mesh).tree, unit).sah;
  INFO(name << ": SAH lbvh " << lbvh << ", binned " << binned);
  CHECK(lbvh > binned);
  CHECK_THROWS_WITH(buildLbvh(mesh, LbvhConfig{0}),
                    "lbvh builder: the maximum leaf size must be at least 1");
}

}  // namespace rtu
