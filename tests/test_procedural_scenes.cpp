#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"

namespace rtu {
namespace {

bool solid(const VoxelSource& source, uint32_t x, uint32_t y, uint32_t z) {
  return source.classify(OctreeNode{source.depth(), x, y, z}) == Occupancy::Full;
}

double centre(uint32_t voxel, int depth) { return (voxel + 0.5) * 2.0 / (1u << depth) - 1.0; }

double radius(uint32_t x, uint32_t y, uint32_t z, int depth) {
  return std::sqrt(std::pow(centre(x, depth), 2) + std::pow(centre(y, depth), 2) +
                   std::pow(centre(z, depth), 2));
}

// Calls `visit(x, y, z)` for every voxel inside `node`.
template <class Visit>
void forEachVoxel(const VoxelSource& source, const OctreeNode& node, Visit visit) {
  const int shift = source.depth() - node.level;
  const uint32_t count = 1u << shift;
  for (uint32_t z = node.z << shift; z < (node.z << shift) + count; ++z)
    for (uint32_t y = node.y << shift; y < (node.y << shift) + count; ++y)
      for (uint32_t x = node.x << shift; x < (node.x << shift) + count; ++x) visit(x, y, z);
}

// An Empty or Full answer for a node must hold for every voxel inside it.
void requireConservative(const VoxelSource& source, const OctreeNode& node) {
  const Occupancy answer = source.classify(node);
  if (answer == Occupancy::Mixed) return;
  size_t disagreeing = 0;
  forEachVoxel(source, node, [&](uint32_t x, uint32_t y, uint32_t z) {
    disagreeing += source.classify(OctreeNode{source.depth(), x, y, z}) != answer;
  });
  INFO("level " << node.level << " node " << node.x << "," << node.y << "," << node.z);
  REQUIRE(disagreeing == 0);
}

size_t countSolid(const VoxelSource& source) {
  size_t count = 0;
  forEachVoxel(source, OctreeNode{},
               [&](uint32_t x, uint32_t y, uint32_t z) { count += solid(source, x, y, z); });
  return count;
}

bool sameVoxels(const VoxelSource& a, const VoxelSource& b) {
  bool same = true;
  forEachVoxel(a, OctreeNode{}, [&](uint32_t x, uint32_t y, uint32_t z) {
    same = same && solid(a, x, y, z) == solid(b, x, y, z);
  });
  return same;
}

TEST_CASE("scenes: the six scenes by name, bad names and depths are refused", "[scenes]") {
  CHECK(proceduralSceneNames() ==
        std::vector<std::string>{"sphere", "shell", "menger", "terrain", "noise", "room"});
  for (const std::string& name : proceduralSceneNames()) {
    CHECK(makeProceduralScene(name, 1)->depth() == 1);
    CHECK(makeProceduralScene(name, 16)->depth() == 16);
    CHECK_THROWS_AS(makeProceduralScene(name, 0), std::invalid_argument);
    CHECK_THROWS_AS(makeProceduralScene(name, 17), std::invalid_argument);
  }
  CHECK_THROWS_WITH(makeProceduralScene("cube", 4),
                    Catch::Contains("'cube'") &&
                        Catch::Contains("sphere, shell, menger, terrain, noise, room"));
}

TEST_CASE("scenes: never Mixed for a voxel, never wrong for a node", "[scenes]") {
  for (const std::string& name : proceduralSceneNames()) {
    INFO(name);
    for (int depth : {1, 2, 5}) {
      const auto source = makeProceduralScene(name, depth, 9);
      forEachVoxel(*source, OctreeNode{}, [&](uint32_t x, uint32_t y, uint32_t z) {
        REQUIRE(source->classify(OctreeNode{depth, x, y, z}) != Occupancy::Mixed);
      });
      for (int level = 0; level < depth; ++level) {
        const uint32_t cells = 1u << level;
        for (uint32_t z = 0; z < cells; ++z)
          for (uint32_t y = 0; y < cells; ++y)
            for (uint32_t x = 0; x < cells; ++x)
              requireConservative(*source, OctreeNode{level, x, y, z});
      }
    }
  }
}

TEST_CASE("scenes: node answers are conservative near the voxel level at depth 8 and 12",
          "[scenes]") {
  std::mt19937 random(11);
  for (const std::string& name : proceduralSceneNames()) {
    for (int depth : {8, 12}) {
      INFO(name << " at depth " << depth);
      const auto source = makeProceduralScene(name, depth, 5);
      std::uniform_int_distribution<uint32_t> coordinate(0, (1u << depth) - 1);
      for (int sample = 0; sample < 40; ++sample) {
        const uint32_t x = coordinate(random), y = coordinate(random), z = coordinate(random);
        for (int level = depth - 4; level <= depth; ++level) {
          const int shift = depth - level;
          requireConservative(*source, OctreeNode{level, x >> shift, y >> shift, z >> shift});
        }
      }
    }
  }
}

TEST_CASE("scenes: sphere of radius 0.8 sampled at voxel centres", "[scenes]") {
  const int depth = 6;
  const auto sphere = makeProceduralScene("sphere", depth);
  CHECK(solid(*sphere, 32, 32, 32));
  CHECK_FALSE(solid(*sphere, 0, 0, 0));
  forEachVoxel(*sphere, OctreeNode{}, [&](uint32_t x, uint32_t y, uint32_t z) {
    REQUIRE(solid(*sphere, x, y, z) == (radius(x, y, z, depth) <= 0.8));
  });
  CHECK(sphere->classify(OctreeNode{1, 0, 0, 0}) == Occupancy::Mixed);
  CHECK(sphere->classify(OctreeNode{3, 3, 3, 3}) == Occupancy::Full);   // [-0.25,0]^3
  CHECK(sphere->classify(OctreeNode{3, 0, 0, 0}) == Occupancy::Empty);  // corner [-1,-0.75]^3
}

TEST_CASE("scenes: uniform regions collapse into leaves", "[scenes]") {
  const auto sphere = makeProceduralScene("sphere", 6);
  const SvoBuild build = buildSvo(*sphere);
  CHECK(build.stats.leaves * 4 < countSolid(*sphere));
}

TEST_CASE("scenes: shell is hollow with a wall of max(0.1, two voxels)", "[scenes]") {
  const int depth = 6;  // voxels 1/32 wide: the wall is 0.1, from radius 0.7 to 0.8
  const auto shell = makeProceduralScene("shell", depth);
  CHECK_FALSE(solid(*shell, 32, 32, 32));
  CHECK(solid(*shell, 56, 32, 32));  // centre x = 0.78125
  CHECK_FALSE(solid(*shell, 0, 0, 0));
  forEachVoxel(*shell, OctreeNode{}, [&](uint32_t x, uint32_t y, uint32_t z) {
    const double r = radius(x, y, z, depth);
    REQUIRE(solid(*shell, x, y, z) == (r >= 0.7 && r <= 0.8));
  });
  CHECK(shell->classify(OctreeNode{3, 3, 3, 3}) == Occupancy::Empty);

  for (int coarse = 3; coarse <= 8; ++coarse) {  // at depth 2 the sphere itself is 2 voxels wide
    INFO("depth " << coarse);
    const auto thin = makeProceduralScene("shell", coarse);
    const uint32_t middle = 1u << (coarse - 1);
    int wall = 0;
    for (uint32_t x = middle; x < 2 * middle; ++x) wall += solid(*thin, x, middle, middle);
    CHECK(wall >= 2);
  }
}

// Point (u, v, w) in the unit cube is removed at iteration i when two of its i-th ternary digits
// are 1.
bool inMenger(const std::array<double, 3>& point, int iterations) {
  double scale = 1;
  for (int i = 1; i <= iterations; ++i) {
    scale *= 3;
    int middles = 0;
    for (double coordinate : point)
      middles += static_cast<int>(std::floor(coordinate * scale)) % 3 == 1;
    if (middles >= 2) return false;
  }
  return true;
}

TEST_CASE("scenes: Menger sponge with as many iterations as the voxels resolve", "[scenes]") {
  const int depth = 5;  // 27 <= 32 < 81: three iterations
  const auto menger = makeProceduralScene("menger", depth);
  CHECK_FALSE(solid(*menger, 16, 16, 16));
  CHECK(solid(*menger, 0, 0, 0));
  CHECK_FALSE(solid(*menger, 16, 16, 0));  // the tunnel along z
  forEachVoxel(*menger, OctreeNode{}, [&](uint32_t x, uint32_t y, uint32_t z) {
    const double scale = 1u << depth;
    REQUIRE(solid(*menger, x, y, z) ==
            inMenger({(x + 0.5) / scale, (y + 0.5) / scale, (z + 0.5) / scale}, 3));
  });

  const auto fine = makeProceduralScene("menger", 8);
  CHECK(fine->classify(OctreeNode{3, 3, 3, 0}) == Occupancy::Empty);  // inside the z tunnel
  CHECK(fine->classify(OctreeNode{3, 0, 0, 0}) == Occupancy::Mixed);
}

TEST_CASE("scenes: terrain answers are conservative around its surface at depth 12", "[scenes]") {
  const int depth = 12;  // beyond the 1024-cell height grid: columns interpolate in a cell
  const auto terrain = makeProceduralScene("terrain", depth, 6);
  std::mt19937 random(3);
  std::uniform_int_distribution<uint32_t> coordinate(0, (1u << depth) - 1);
  for (int sample = 0; sample < 40; ++sample) {
    const uint32_t x = coordinate(random), z = coordinate(random);
    uint32_t surface = 0;  // lowest empty voxel of the column
    for (uint32_t step = 1u << (depth - 1); step > 0; step >>= 1)
      if (solid(*terrain, x, surface + step - 1, z)) surface += step;
    for (int level = depth - 5; level <= depth; ++level) {
      const int shift = depth - level;
      requireConservative(*terrain, OctreeNode{level, x >> shift, surface >> shift, z >> shift});
    }
  }
}

TEST_CASE("scenes: terrain is a seeded height field, y up", "[scenes]") {
  const int depth = 6;
  const uint32_t side = 1u << depth;
  const auto terrain = makeProceduralScene("terrain", depth, 4);
  uint32_t lowest = side;
  uint32_t highest = 0;
  for (uint32_t z = 0; z < side; ++z) {
    for (uint32_t x = 0; x < side; ++x) {
      uint32_t height = 0;
      while (height < side && solid(*terrain, x, height, z)) ++height;
      for (uint32_t y = height; y < side; ++y) REQUIRE_FALSE(solid(*terrain, x, y, z));
      lowest = std::min(lowest, height);
      highest = std::max(highest, height);
    }
  }
  CHECK(lowest > 0);
  CHECK(highest < side);
  CHECK(highest - lowest >= 8);

  CHECK(sameVoxels(*terrain, *makeProceduralScene("terrain", depth, 4)));
  CHECK_FALSE(sameVoxels(*terrain, *makeProceduralScene("terrain", depth, 5)));
}

TEST_CASE("scenes: noise is seeded white noise of density 1/32", "[scenes]") {
  const int depth = 6;
  const auto noise = makeProceduralScene("noise", depth, 4);
  const double density = static_cast<double>(countSolid(*noise)) / (1u << 3 * depth);
  CHECK(density == Approx(1.0 / 32).epsilon(0.05));
  CHECK(sameVoxels(*noise, *makeProceduralScene("noise", depth, 4)));
  CHECK_FALSE(sameVoxels(*noise, *makeProceduralScene("noise", depth, 5)));
}

TEST_CASE("scenes: room has walls an eighth thick, its front open, furniture inside", "[scenes]") {
  const int depth = 5;  // voxels 1/16 wide, centres at (2v + 1) / 32 - 1
  const auto room = makeProceduralScene("room", depth);
  const uint32_t last = (1u << depth) - 1;
  // Floor, ceiling, side and back walls span [-1, -0.875] and [0.875, 1]: the outer two layers
  // but the front's (z = -1), which is open.
  forEachVoxel(*room, OctreeNode{}, [&](uint32_t x, uint32_t y, uint32_t z) {
    const bool wall = std::min(x, y) < 2 || std::max({x, y, z}) > last - 2;
    if (wall) REQUIRE(solid(*room, x, y, z));
  });
  CHECK_FALSE(solid(*room, 16, 16, 0));   // the open front
  CHECK_FALSE(solid(*room, 16, 2, 16));   // centre y -0.84375: just above the floor
  CHECK_FALSE(solid(*room, 16, 16, 8));   // (0.03125, 0.03125, -0.46875): open air
  CHECK(solid(*room, 16, 10, 20));        // (0.03125, -0.34375, 0.28125): the table top
  CHECK_FALSE(solid(*room, 16, 9, 20));   // y -0.40625: under it
  CHECK(solid(*room, 16, 25, 21));        // (0.03125, 0.59375, 0.34375): in the lamp, r 0.125
  CHECK_FALSE(solid(*room, 16, 28, 21));  // y 0.78125: above it
  CHECK(solid(*room, 16, 10, 14));        // (0.03125, -0.34375, -0.09375): the chair's back
  CHECK_FALSE(solid(*room, 16, 10, 13));  // z -0.15625: behind it
}

}  // namespace
}  // namespace rtu
