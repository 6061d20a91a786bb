// .binvox import: orientation, padding, node classification, round trips and malformed files.
#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "kinds/svo/binvox.h"
#include "kinds/svo/svo_builder.h"
#include "temp_path.h"

using namespace rtu;
using Catch::Matchers::Contains;

namespace {

// A binvox file written byte by byte: `header` verbatim, then the run bytes.
void writeRaw(const std::string& path, const std::string& header,
              const std::vector<uint8_t>& runs) {
  std::ofstream out(path, std::ios::binary);
  out << header;
  out.write(reinterpret_cast<const char*>(runs.data()), static_cast<std::streamsize>(runs.size()));
}

using Pattern = std::function<bool(int, int, int)>;

// What a node should be: Empty, Full or Mixed from the pattern's voxels (beyond `dim`: empty).
Occupancy bruteForce(const Pattern& solid, int dim, int depth, const OctreeNode& node) {
  const uint32_t span = 1u << (depth - node.level);
  int64_t count = 0;
  for (uint32_t x = node.x * span; x < (node.x + 1) * span; ++x)
    for (uint32_t y = node.y * span; y < (node.y + 1) * span; ++y)
      for (uint32_t z = node.z * span; z < (node.z + 1) * span; ++z)
        count += static_cast<int>(x) < dim && static_cast<int>(y) < dim &&
                 static_cast<int>(z) < dim && solid(x, y, z);
  if (count == 0) return Occupancy::Empty;
  return count == int64_t{span} * span * span ? Occupancy::Full : Occupancy::Mixed;
}

// Every node of every level of `grid` against the brute-force answer.
void requireMatchesPattern(const BinvoxGrid& grid, const Pattern& solid, int dim) {
  for (int level = 0; level <= grid.depth(); ++level) {
    const uint32_t cells = 1u << level;
    for (uint32_t x = 0; x < cells; ++x)
      for (uint32_t y = 0; y < cells; ++y)
        for (uint32_t z = 0; z < cells; ++z) {
          const OctreeNode node{level, x, y, z};
          if (grid.classify(node) != bruteForce(solid, dim, grid.depth(), node)) {
            INFO("level " << level << " node " << x << " " << y << " " << z);
            REQUIRE(grid.classify(node) == bruteForce(solid, dim, grid.depth(), node));
          }
        }
  }
}

const Pattern kSphere = [](int x, int y, int z) {
  auto square = [](double d) { return d * d; };
  return square(x + 0.5 - 16) + square(y + 0.5 - 16) + square(z + 0.5 - 16) <= square(14);
};

}  // namespace

TEST_CASE("binvox voxel order is x, then z, then y fastest, with y mapped to octree y",
          "[binvox]") {
  // binvox index = x * D * D + z * D + y. In a 2^3 grid, index 1 is (x 0, y 1, z 0), index 2 is
  // (0, 0, 1), index 4 is (1, 0, 0).
  const TempPath path("order.binvox");
  const std::string header = "#binvox 1\ndim 2 2 2\ntranslate 0 0 0\nscale 1\ndata\n";
  struct Case {
    int index;
    OctreeNode voxel;
  };
  for (const Case& c : {Case{1, {1, 0, 1, 0}}, Case{2, {1, 0, 0, 1}}, Case{4, {1, 1, 0, 0}}}) {
    std::vector<uint8_t> runs;
    if (c.index > 0) runs.insert(runs.end(), {0, static_cast<uint8_t>(c.index)});
    runs.insert(runs.end(), {1, 1, 0, static_cast<uint8_t>(7 - c.index)});
    writeRaw(path.str(), header, runs);
    const BinvoxGrid grid(path.str());
    INFO("binvox index " << c.index);
    CHECK(grid.solidVoxels() == 1);
    for (int slot = 0; slot < 8; ++slot) {
      const OctreeNode voxel = OctreeNode{}.child(slot);
      const bool expected = voxel.x == c.voxel.x && voxel.y == c.voxel.y && voxel.z == c.voxel.z;
      CHECK(grid.classify(voxel) == (expected ? Occupancy::Full : Occupancy::Empty));
    }
  }
}

TEST_CASE("A sphere survives writeBinvox and BinvoxGrid at every level", "[binvox]") {
  const TempPath path("sphere.binvox");
  writeBinvox(path.str(), 32, kSphere);
  const BinvoxGrid grid(path.str());
  REQUIRE(grid.dim() == 32);
  REQUIRE(grid.depth() == 5);
  CHECK(grid.translate() == glm::dvec3(0.0));
  CHECK(grid.scale() == 1.0);
  requireMatchesPattern(grid, kSphere, 32);
  // Voxels 8..15 lie within 13 of the centre: inside the radius 14. Voxels 0..7 lie beyond.
  CHECK(grid.classify(OctreeNode{2, 1, 1, 1}) == Occupancy::Full);
  CHECK(grid.classify(OctreeNode{2, 0, 0, 0}) == Occupancy::Empty);
  CHECK(grid.classify(OctreeNode{}) == Occupancy::Mixed);

  const SvoBuild build = buildSvo(grid);
  CHECK(build.stats.depth == 5);
  CHECK(build.stats.descriptors > 1);
}

TEST_CASE("A non-power-of-two binvox grid is padded with empty voxels", "[binvox]") {
  const TempPath path("padded.binvox");
  const Pattern all = [](int, int, int) { return true; };
  writeBinvox(path.str(), 20, all);
  const BinvoxGrid grid(path.str());
  REQUIRE(grid.depth() == 5);  // 20 voxels round up to 32
  CHECK(grid.solidVoxels() == 20 * 20 * 20);
  requireMatchesPattern(grid, all, 20);
  CHECK(grid.classify(OctreeNode{1, 0, 0, 0}) == Occupancy::Full);   // voxels 0..15
  CHECK(grid.classify(OctreeNode{1, 1, 1, 1}) == Occupancy::Mixed);  // 16..19 solid, 20.. empty
  CHECK(grid.classify(OctreeNode{5, 25, 0, 0}) == Occupancy::Empty);
  CHECK(grid.classify(OctreeNode{5, 19, 19, 19}) == Occupancy::Full);

  SECTION("a single voxel becomes a depth-1 grid") {
    writeBinvox(path.str(), 1, all);
    const BinvoxGrid single(path.str());
    CHECK(single.depth() == 1);
    CHECK(single.classify(OctreeNode{1, 0, 0, 0}) == Occupancy::Full);
    CHECK(single.classify(OctreeNode{1, 1, 0, 0}) == Occupancy::Empty);
    CHECK(buildSvo(single).stats.leaves == 1);
  }
}

TEST_CASE("Long runs are split at 255 and translate and scale are read", "[binvox]") {
  const TempPath path("runs.binvox");
  // 64^3 solid voxels: 1028 runs of 255 and one of 4, after a header with extra whitespace and
  // a keyword binvox's reader would skip.
  std::vector<uint8_t> runs;
  for (int i = 0; i < 64 * 64 * 64 / 255; ++i) runs.insert(runs.end(), {1, 255});
  runs.insert(runs.end(), {1, 64 * 64 * 64 % 255});
  writeRaw(path.str(),
           "#binvox 1\r\ndim  64 64 64\r\ncomment made by hand\ntranslate -1.5 2 0.25\n"
           "scale 3.5\ndata\n",
           runs);
  const BinvoxGrid grid(path.str());
  CHECK(grid.solidVoxels() == 64 * 64 * 64);
  CHECK(grid.classify(OctreeNode{}) == Occupancy::Full);
  CHECK(grid.translate() == glm::dvec3(-1.5, 2, 0.25));
  CHECK(grid.scale() == 3.5);
}

TEST_CASE("Malformed binvox files are rejected with the file and the problem", "[binvox]") {
  const TempPath path("bad.binvox");
  const std::string dim2 = "#binvox 1\ndim 2 2 2\ndata\n";
  struct Case {
    const char* name;
    std::string header;
    std::vector<uint8_t> runs;
    std::string problem;
  };
  const std::vector<Case> cases = {
      {"empty file", "", {}, "is empty"},
      {"bad magic", "#binvax 1\ndim 2 2 2\ndata\n", {0, 8}, "line 1: bad magic"},
      {"other version", "#binvox 2\ndim 2 2 2\ndata\n", {0, 8}, "unsupported binvox version"},
      {"missing dims", "#binvox 1\ndata\n", {0, 8}, "no 'dim' line before 'data'"},
      {"two dims", "#binvox 1\ndim 2 2\ndata\n", {0, 8}, "line 2: 'dim 2 2' must hold three"},
      {"odd dims", "#binvox 1\ndim 2 two 2\ndata\n", {0, 8}, "must hold three whole numbers"},
      {"fractional dims", "#binvox 1\ndim 2 2 2.5\ndata\n", {0, 8}, "three whole numbers"},
      {"non-cubic", "#binvox 1\ndim 2 2 4\ndata\n", {0, 16}, "dimensions 2 2 4 are not cubic"},
      {"dim 0", "#binvox 1\ndim 0 0 0\ndata\n", {}, "dimension 0 is outside 1 to 4096"},
      {"dim too large",
       "#binvox 1\ndim 8192 8192 8192\ndata\n",
       {0, 8},
       "dimension 8192 is outside 1 to 4096"},
      {"bad translate",
       "#binvox 1\ndim 2 2 2\ntranslate 1 2\ndata\n",
       {0, 8},
       "line 3: 'translate 1 2' must hold three numbers"},
      {"no data line", "#binvox 1\ndim 2 2 2\n", {}, "header has no 'data' line"},
      {"run overflow", dim2, {1, 5, 0, 4}, "run at byte 27 overflows the grid"},
      {"trailing run", dim2, {1, 8, 0, 1}, "runs cover more than its 8 voxels"},
      {"run underflow", dim2, {1, 5, 0, 2}, "runs cover only 7 of 8 voxels"},
      {"no runs", dim2, {}, "runs cover only 0 of 8 voxels"},
      {"truncated run", dim2, {1, 5, 0}, "ends inside the run at byte 27"},
      {"bad value", dim2, {1, 4, 2, 4}, "run at byte 27 has value 2 (must be 0 or 1)"},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    writeRaw(path.str(), c.header, c.runs);
    CHECK_THROWS_AS(BinvoxGrid(path.str()), std::runtime_error);
    CHECK_THROWS_WITH(BinvoxGrid(path.str()),
                      Contains("binvox file '" + path.str() + "'") && Contains(c.problem));
  }
  CHECK_THROWS_WITH(BinvoxGrid("/nonexistent/grid.binvox"),
                    Contains("cannot open binvox file '/nonexistent/grid.binvox'"));
}

TEST_CASE("writeBinvox and classify reject bad parameters", "[binvox]") {
  const TempPath path("params.binvox");
  const Pattern none = [](int, int, int) { return false; };
  CHECK_THROWS_AS(writeBinvox(path.str(), 0, none), std::invalid_argument);
  CHECK_THROWS_WITH(writeBinvox(path.str(), 4097, none), Contains("dim must be 1 to 4096"));
  CHECK_THROWS_WITH(writeBinvox("/nonexistent/dir/x.binvox", 2, none), Contains("cannot create"));

  writeBinvox(path.str(), 4, none);
  const BinvoxGrid grid(path.str());
  CHECK(grid.classify(OctreeNode{}) == Occupancy::Empty);
  CHECK_THROWS_AS(grid.classify(OctreeNode{3, 0, 0, 0}), std::invalid_argument);
  CHECK_THROWS_AS(grid.classify(OctreeNode{1, 2, 0, 0}), std::invalid_argument);
}
