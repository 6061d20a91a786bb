// Seed 001's scene files byte for byte against the team's own (R1, github.com/ryanmacdonald/18-545
// at 81a34cd). R1 has no licence, so its files are never in rtusim: scripts/extract_trayracer.sh
// extracts them, and these tests read RTUSIM_TRAYRACER_DIR at run time. Without it they warn and
// check nothing (Catch2 2.13 has no skip). The files' helpers are trayracer_r1.h's.
#include <catch2/catch.hpp>

#include "trayracer_r1.h"

namespace rtu {
namespace {

// The figures of plan §2, from the nodes alone; depth in edges from the root.
struct TreeFigures {
  size_t nodes = 0, depth = 0, leaves = 0, emptyLeaves = 0, listEntries = 0, maxPerLeaf = 0;
};

TreeFigures figures(const TrayRacerScene& scene) {
  TreeFigures f;
  f.nodes = scene.nodes.size();
  f.listEntries = scene.lists.size();
  std::vector<std::pair<uint32_t, size_t>> pending{{0, 0}};
  while (!pending.empty()) {
    const auto [id, depth] = pending.back();
    pending.pop_back();
    f.depth = std::max(f.depth, depth);
    const TrayRacerNode& node = scene.nodes.at(id);
    if (node.leaf) {
      ++f.leaves;
      f.emptyLeaves += node.count == 0;
      f.maxPerLeaf = std::max<size_t>(f.maxPerLeaf, node.count);
    } else {
      pending.push_back({id + 1, depth + 1});
      pending.push_back({node.high, depth + 1});
    }
  }
  return f;
}

TEST_CASE("R1 scene files: read then written back byte for byte", "[kd][kd_r1]") {
  if (!trayRacerDir()) {
    WARN("RTUSIM_TRAYRACER_DIR unset (scripts/extract_trayracer.sh): R1 files not checked");
    return;
  }
  for (const char* name : {"bunny_color_aabb", "elephant", "t4s3_color_aabb"}) {
    INFO(name);
    const std::vector<uint8_t> bytes =
        readBytes(std::string(trayRacerDir()) + "/SCENES/" + name + ".scene");
    CHECK(writeTrayRacerScene(readTrayRacerScene(bytes, TrayRacerFormat::Narrow),
                              TrayRacerFormat::Narrow) == bytes);
  }
}

// Plan §2's table, decoded from R1's files.
TEST_CASE("R1 scene files: the structural figures", "[kd][kd_r1]") {
  if (!trayRacerDir()) return;
  struct Row {
    const char* name;
    TreeFigures expected;
  };
  for (const Row& row : {Row{"bunny_color_aabb", {3381, 18, 1691, 253, 3376, 10}},
                         Row{"elephant", {14587, 21, 7294, 1003, 17360, 15}},
                         Row{"t4s3_color_aabb", {7, 2, 4, 0, 6, 2}}}) {
    INFO(row.name);
    const TreeFigures f = figures(readTrayRacerScene(
        readBytes(std::string(trayRacerDir()) + "/SCENES/" + row.name + ".scene"),
        TrayRacerFormat::Narrow));
    CHECK(f.nodes == row.expected.nodes);
    CHECK(f.depth == row.expected.depth);
    CHECK(f.leaves == row.expected.leaves);
    CHECK(f.emptyLeaves == row.expected.emptyLeaves);
    CHECK(f.listEntries == row.expected.listEntries);
    CHECK(f.maxPerLeaf == row.expected.maxPerLeaf);
  }
}

TEST_CASE("rtusim's builder reproduces R1's elephant.scene", "[kd][kd_r1]") {
  if (!trayRacerDir()) return;
  const std::string dir = trayRacerDir();
  const TrayRacerScene built = buildElephant(dir);
  // The file keeps 28 bits of each split: compare nodes as written.
  const TrayRacerScene written = readTrayRacerScene(
      writeTrayRacerScene(built, TrayRacerFormat::Narrow), TrayRacerFormat::Narrow);
  const TrayRacerScene r1 =
      readTrayRacerScene(readBytes(dir + "/SCENES/elephant.scene"), TrayRacerFormat::Narrow);
  // Section by section, so that a failure says which.
  CHECK(built.box == r1.box);
  CHECK(built.uttms == r1.uttms);
  CHECK(built.shades == r1.shades);
  CHECK(written.nodes.size() == r1.nodes.size());
  CHECK(written.nodes == r1.nodes);
  CHECK(built.lists == r1.lists);
  const std::vector<std::string> warnings = trayRacerCapacityWarnings(built);
  REQUIRE(warnings.size() == 2);  // nodes and list entries; 1023 triangles fit
  CHECK_THAT(warnings[0], Catch::Contains("14587 exceeds the Tray Racer's 4096"));
  CHECK_THAT(warnings[1], Catch::Contains("17360 exceeds the Tray Racer's 16384"));
  CHECK(writeTrayRacerScene(built, TrayRacerFormat::Narrow) ==
        readBytes(dir + "/SCENES/elephant.scene"));
}

}  // namespace
}  // namespace rtu
