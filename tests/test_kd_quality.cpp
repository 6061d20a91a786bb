// The k-d tree's quality figures (kinds/kd/kd_quality.h) on a hand-made build: cells cut by the
// splits, leaves with and without triangles, a triangle listed twice, both SAH weightings.
#include <catch2/catch.hpp>

#include "kinds/kd/kd_quality.h"

namespace rtu {

TEST_CASE("k-d quality: cells, leaves and both SAH weightings by hand", "[kd]") {
  // Bounds [0,4] x [0,1] x [0,1] (area 2 (4 + 1 + 4) = 18). The root splits x at 1: below [0,1]
  // (area 6), a leaf of triangles 0 and 1; above [1,4] (area 14) splits x at 3 into [1,3] (area
  // 10), an empty leaf, and [3,4] (area 6), a leaf of triangle 1 again.
  KdBuild build;
  build.bounds = Aabb<float>{{0, 0, 0}, {4, 1, 1}};
  build.lists = {0, 1, 1};
  build.nodes.resize(5);
  build.nodes[0] = {false, 0, 1.0f, 2};
  build.nodes[1] = {true, 0, 0, 0, false, false, 0, 2};
  build.nodes[2] = {false, 0, 3.0f, 4};
  build.nodes[3] = {true, 0, 0, 0, false, false, 2, 0};
  build.nodes[4] = {true, 0, 0, 0, false, false, 2, 1};
  const AccelQuality q = measureQuality(build, PbrtKdParameters{});
  CHECK(q.nodes == 5);
  CHECK(q.leaves == 3);
  CHECK(q.emptyLeaves == 1);
  CHECK(q.depth == 2);
  CHECK(q.listEntries == 3);
  CHECK(q.triangles == 2);
  CHECK(q.trianglesPerLeafMax == 2);
  CHECK(q.trianglesPerLeafMean == 1.0);
  // Inner areas 18 + 14 = 32; leaf areas times counts 6*2 + 10*0 + 6*1 = 18.
  CHECK(q.sah == Approx((32.0 + 18.0) / 18.0));
  CHECK(q.sahSeed == Approx((32.0 + 80.0 * 18.0) / 18.0));
}

}  // namespace rtu
