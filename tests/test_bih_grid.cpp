// Seed 004's n-bit grid (kinds/bih/grid.h) on hand cases: the scene box [0, 30] x [0, 10] x
// [0, 10] on a 4-bit grid has scale (2^4 - 1) / 30 = 1/2 grid unit per world unit, so every
// product below is exact and each rounding is visible.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

#include "bih_formats.h"
#include "kinds/bih/grid.h"

namespace rtu {
namespace {

SceneGrid wideBox(const FixedTriangleFormat& format = kFourBit) {
  Aabb<double> box;
  box.grow({0, 0, 0});
  box.grow({30, 10, 10});
  return SceneGrid(box, format);
}

}  // namespace

TEST_CASE("BIH grid: one scale, vertices rounded half to even", "[bih]") {
  const SceneGrid grid = wideBox();
  CHECK(grid.scale() == 0.5);
  // (5, 3, 1) / 2 = (2.5, 1.5, 0.5): halves go to the even neighbour.
  CHECK(grid.quantise({5, 3, 1}) == GridPoint{2, 2, 0});
  // The far corner: 30 / 2 = 15 = 2^4 - 1.
  CHECK(grid.quantise({30, 10, 10}) == GridPoint{15, 5, 5});
}

TEST_CASE("BIH grid: a ray is clipped to the box before it is quantised", "[bih]") {
  const SceneGrid grid = wideBox();
  // From x = -10 along +x at speed 2: it enters the box at x = 0, t = 5.
  const auto ray = grid.quantise(Ray{{-10, 4, 4}, {2, 0, 0}});
  REQUIRE(ray);
  CHECK(ray->tClip == 5);
  CHECK(ray->origin == GridPoint{0, 2, 2});
  // +1 is not representable at scale 2^(m-1) = 32: it saturates to 31.
  CHECK(ray->omega == GridPoint{31, 0, 0});
  // A grid unit is 2 world units, the direction 2 long: one unit of t. 10 grid units in, the
  // world ray is at t = 5 + 10 = 15, x = -10 + 30 = 20, which is grid x = 10.
  CHECK(ray->worldPerGridUnit == 1);
  CHECK(ray->worldT(10) == 15);
  // The unit diagonal (1, -1, 0) / sqrt 2: 32 / sqrt 2 = 22.63 rounds to 23.
  const auto diagonal = grid.quantise(Ray{{1, 5, 5}, {1, -1, 0}});
  REQUIRE(diagonal);
  CHECK(diagonal->omega == GridPoint{23, -23, 0});
  CHECK(diagonal->tClip == 0);  // starts inside
}

TEST_CASE("BIH grid: rays that miss the box have no grid ray", "[bih]") {
  const SceneGrid grid = wideBox();
  CHECK_FALSE(grid.quantise(Ray{{-10, 20, 4}, {1, 0, 0}}));  // passes above
  CHECK_FALSE(grid.quantise(Ray{{40, 4, 4}, {1, 0, 0}}));    // points away
  CHECK_THROWS_AS(grid.quantise(Ray{{1, 1, 1}, {0, 0, 0}}), std::invalid_argument);
}

TEST_CASE("BIH grid: the inverse direction of each listing", "[bih]") {
  // m = 6, C = 2. VHDL: trunc(2^(m-1+C) / ω) = trunc(128 / ω), within ±(2^(m+C-1) - 1) = ±127.
  CHECK(inverseDirection(31, kFourBit) == 4);    // 128 / 31 = 4.13
  CHECK(inverseDirection(-32, kFourBit) == -4);  // -1.0 exactly
  CHECK(inverseDirection(0, kFourBit) == 127);   // as ω = 1 code: 128, saturated
  // C99 as printed: 2^(m+C) / ω = 256 / ω, twice the VHDL's scale, no saturation.
  FixedTriangleFormat c99 = kFourBit;
  c99.listing = FixedListing::C99;
  CHECK(inverseDirection(31, c99) == 8);  // 256 / 31 = 8.26
  CHECK(inverseDirection(0, c99) == 256);
}

TEST_CASE("BIH grid: formats outside the records' widths are refused", "[bih]") {
  Aabb<double> box;
  box.grow({0, 0, 0});
  box.grow({1, 1, 1});
  FixedTriangleFormat wide = kC99Format;
  wide.n = 31;
  CHECK_THROWS_AS(SceneGrid(box, wide), std::invalid_argument);
  FixedTriangleFormat vhdl = kVhdlFormat;
  vhdl.m = 31;  // the VHDL needs m = n + 2
  CHECK_THROWS_AS(SceneGrid(box, vhdl), std::invalid_argument);
  CHECK_NOTHROW(SceneGrid(box, kC99Format));
  CHECK_NOTHROW(SceneGrid(box, kVhdlFormat));
  Aabb<double> point;
  point.grow({1, 1, 1});
  CHECK_THROWS_AS(SceneGrid(point, kC99Format), std::invalid_argument);
}

}  // namespace rtu
