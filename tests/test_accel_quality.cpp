// Quality figures of triangle structures (geometry/accel_quality.h): the SAH sum by hand and the
// JSON keys the issue names.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "geometry/accel_quality.h"

namespace rtu {

// A root of area 24 over two leaves of area 12 with 6 triangles each: unit costs give
// (24 + 12·6 + 12·6) / 24 = 7; box 1 and triangle 2 (seed 003) give (24 + 2·144) / 24 = 13.
TEST_CASE("SahSum: inner areas and leaf areas times triangles over the root's", "[bvh]") {
  SahSum sum;
  sum.addInner(24);
  sum.addLeaf(12, 6);
  sum.addLeaf(12, 6);
  CHECK(sum.cost(24, SahCosts{}) == 7.0);
  CHECK(sum.cost(24, SahCosts{1.0, 2.0}) == 13.0);
  CHECK(std::isnan(SahSum{}.cost(0, SahCosts{})));  // no root area, no SAH
}

TEST_CASE("AccelQuality: the issue's JSON keys, a NaN as null", "[bvh]") {
  AccelQuality quality;
  quality.triangles = 12;
  quality.nodes = 3;
  quality.leaves = 2;
  quality.depth = 1;
  quality.listEntries = 12;
  quality.trianglesPerLeafMean = 6;
  quality.trianglesPerLeafMax = 6;
  quality.sah = 7;
  quality.sahSeed = std::numeric_limits<double>::quiet_NaN();
  quality.bytes = 784;
  quality.buildSeconds = 0.5;
  const nlohmann::json json = quality;
  CHECK(
      json.dump() ==
      R"({"build_seconds":0.5,"bytes":784,"depth":1,"empty_leaves":0,"leaves":2,"list_entries":12,)"
      R"("nodes":3,)"
      R"("sah":7.0,"sah_seed":null,"triangles":12,"triangles_per_leaf_max":6,)"
      R"("triangles_per_leaf_mean":6.0})");
}

}  // namespace rtu
