// A BVH's quality figures (kinds/bvh/bvh_quality.h) on the langr builder's hand-derived trees.
#include <catch2/catch.hpp>

#include <vector>

#include "bvh_meshes.h"
#include "kinds/bvh/bvh_quality.h"
#include "kinds/bvh/langr_builder.h"

namespace rtu {

// A box over row triangles of centres a..b has area 2 (b - a + 1) (bvh_meshes.h).
TEST_CASE("BVH quality: counts and SAH of the langr trees by hand", "[bvh]") {
  const SahCosts seed{1.0, 2.0};
  SECTION("12 in a row: a root of area 24 over two leaves of area 12 with 6 each") {
    const AccelQuality quality = measureQuality(buildLangr(rowOfTriangles(12)).tree, seed);
    CHECK(quality.triangles == 12);
    CHECK(quality.nodes == 3);
    CHECK(quality.leaves == 2);
    CHECK(quality.emptyLeaves == 0);
    CHECK(quality.depth == 1);
    CHECK(quality.listEntries == 12);
    CHECK(quality.trianglesPerLeafMean == 6.0);
    CHECK(quality.trianglesPerLeafMax == 6);
    CHECK(quality.sah == 7.0);       // (24 + 12·6 + 12·6) / 24
    CHECK(quality.sahSeed == 13.0);  // (24 + 2·(12·6 + 12·6)) / 24
    CHECK(quality.bytes == 0);       // the caller's
  }
  SECTION("9 in a row: the root leaf") {
    const AccelQuality quality = measureQuality(buildLangr(rowOfTriangles(9)).tree, seed);
    CHECK(quality.depth == 0);
    CHECK(quality.leaves == 1);
    CHECK(quality.sah == 9.0);
    CHECK(quality.sahSeed == 18.0);
  }
  SECTION("22 coinciding: 3 inner nodes and leaves of 5, 6, 5, 6, every box of area 2") {
    const AccelQuality quality =
        measureQuality(buildLangr(rowOfTriangles(std::vector<double>(22, 0.0))).tree, seed);
    CHECK(quality.depth == 2);
    CHECK(quality.leaves == 4);
    CHECK(quality.trianglesPerLeafMean == 5.5);
    CHECK(quality.trianglesPerLeafMax == 6);
    CHECK(quality.sah == 25.0);      // (3·2 + 2·22) / 2
    CHECK(quality.sahSeed == 47.0);  // (3·2 + 2·2·22) / 2
  }
}

}  // namespace rtu
