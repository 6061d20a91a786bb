// The ray pipe's primary ray generator (raypipe/primary_rays.h) and camera registers
// (raypipe/raypipe_camera.h): the seed's block order (S1 §2.6.2's 40x30 and 80x60 tables), its
// first ray and pixel ids, directions worked out by hand in the RTL's binary32 order, the
// generalisation to other sizes, and rtusim's camera converted to the seed's registers.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <set>
#include <vector>

#include <glm/geometric.hpp>

#include "raypipe/primary_rays.h"
#include "raypipe/raypipe_camera.h"

namespace rtu {
namespace {

uint32_t bitsOf(float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

float floatOf(uint32_t bits) {
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// Block n (1-based, as S1 numbers them) of a frame whose block rows, top first, are `table`:
// every one of its 300 pixels is issued in the n-th run of 300, and the run starts at the block's
// top-left corner.
void checkBlockTable(PrgFrameSize size, const std::vector<std::vector<int>>& table) {
  const std::vector<PrgPixel> order = prgIssueOrder(size);
  REQUIRE(order.size() == static_cast<size_t>(size.width * size.height));
  for (size_t row = 0; row < table.size(); ++row)
    for (size_t column = 0; column < table[row].size(); ++column) {
      const size_t first = static_cast<size_t>(table[row][column] - 1) * 300;
      INFO("block " << table[row][column]);
      CHECK(order[first].x == static_cast<int>(column) * 20);
      CHECK(order[first].y == static_cast<int>(row) * 15);
      for (size_t i = first; i < first + 300; ++i) {
        CHECK(order[i].x / 20 == static_cast<int>(column));
        CHECK(order[i].y / 15 == static_cast<int>(row));
      }
    }
}

}  // namespace

TEST_CASE("PRG blocks go in S1's Z order at 40x30 and 80x60", "[raypipe][prg]") {
  checkBlockTable(prgLevelSize(1), {{1, 2}, {3, 4}});
  checkBlockTable(prgLevelSize(2), {{1, 2, 5, 6}, {3, 4, 7, 8}, {9, 10, 13, 14}, {11, 12, 15, 16}});
}

TEST_CASE("PRG levels\\, first ray\\, order inside a block and pixel ids", "[raypipe][prg]") {
  CHECK(prgLevelSize(0).width == 20);
  CHECK(prgLevelSize(0).height == 15);
  CHECK(prgLevelSize(5).width == 640);
  CHECK(prgLevelSize(5).height == 480);
  CHECK_THROWS_WITH(prgLevelSize(6), Catch::Contains("raypipe.level"));
  const std::vector<PrgPixel> order = prgIssueOrder(prgLevelSize(5));
  // "The first ray will be sent out at the top-left corner of box 1", then x runs to 19, then
  // the next row down.
  CHECK(order[0].x == 0);
  CHECK(order[0].y == 0);
  CHECK(order[19].x == 19);
  CHECK(order[20].x == 0);
  CHECK(order[20].y == 1);
  CHECK(order[299].x == 19);
  CHECK(order[299].y == 14);
  CHECK(order[300].x == 20);  // block 2, right of block 1
  CHECK(order[300].y == 0);
  // pixelID = (rows - 1 - y_prg) cols + x with y_prg from the bottom: row 3 from the top of 480
  // is y_prg 476, so pixel (5, 3) is (479 - 476) 640 + 5.
  std::set<uint32_t> ids;
  for (const PrgPixel& p : order) {
    ids.insert(p.pixelId);
    if (p.x == 5 && p.y == 3) CHECK(p.pixelId == 1925);
  }
  CHECK(ids.size() == 640 * 480);
  CHECK(*ids.rbegin() == 640 * 480 - 1);
}

TEST_CASE("PRG frames end where the RTL's done fires at every level", "[raypipe][prg]") {
  // done = done_sub_box && pixelID == num_rays - 1: the last ray closes a block (x = 19 and
  // y_prg = 0 in it) and has the last pixel id, 300 * 4^level - 1.
  for (int level = 0; level < kPrgLevels; ++level) {
    INFO("level " << level);
    const std::vector<PrgPixel> order = prgIssueOrder(prgLevelSize(level));
    const uint32_t rays = 300u << (2 * level);
    REQUIRE(order.size() == rays);
    CHECK(order.back().pixelId == rays - 1);
    CHECK(order.back().x % 20 == 19);
    CHECK(order.back().y % 15 == 14);
  }
}

TEST_CASE("PRG order for sizes that are not the seed's levels", "[raypipe][prg]") {
  // 60x45 is 3x3 blocks: the Z order of a 4x4 grid with its outside codes skipped.
  const std::vector<PrgPixel> tiled = prgIssueOrder({60, 45});
  const int expected[9][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 0},
                              {2, 1}, {0, 2}, {1, 2}, {2, 2}};
  for (int block = 0; block < 9; ++block) {
    INFO("block " << block);
    CHECK(tiled[block * 300].x == expected[block][0] * 20);
    CHECK(tiled[block * 300].y == expected[block][1] * 15);
  }
  // 30x20 is not tiled: row by row from the top, so issue order is pixel id order.
  const std::vector<PrgPixel> rows = prgIssueOrder({30, 20});
  for (size_t i = 0; i < rows.size(); ++i) CHECK(rows[i].pixelId == i);
  CHECK(rows[31].x == 1);
  CHECK(rows[31].y == 1);
}

TEST_CASE("PRG directions as the RTL computes them", "[raypipe][prg]") {
  const RaypipeCamera reset;  // E = INIT_CAM, U, V, W the unit axes
  const auto direction = [](const KdRay& ray) {
    return std::array<float, 3>{ray.direction[0], ray.direction[1], ray.direction[2]};
  };
  // 640x480, pixel (0, 0): x = 0, y_prg = 479: (0 - 320, 479 - 240, 240).
  CHECK(direction(prgRay(reset, prgLevelSize(5), 0, 0)) == std::array<float, 3>{-320, 239, 240});
  // 20x15 (pw = 32), pixel (0, 0): y_prg = 14, 14 * 32 - 240 = 208.
  CHECK(direction(prgRay(reset, prgLevelSize(0), 0, 0)) == std::array<float, 3>{-320, 208, 240});
  // Its last pixel, (19, 14): 19 * 32 - 320 = 288, y_prg = 0.
  CHECK(direction(prgRay(reset, prgLevelSize(0), 19, 14)) == std::array<float, 3>{288, -240, 240});
  const KdRay first = prgRay(reset, prgLevelSize(5), 0, 0);
  CHECK(first.origin == std::array<float, 3>{1.125f, 1.125f, -1.25f});
  // The table's 45-degree turn about y (sqrt(2)/2 = 0x3F3504F3), pixel (1, 0) at 640x480:
  // u = -319, v = 239; x = (-319 r + 239 * 0) + 240 r = -225.567062 + 169.705627 rounded, worked
  // out apart in float32 as 0xC25F721C, and z = (319 r + 0) + 240 r as 0x43C5A2E8.
  const float r = floatOf(0x3F3504F3);
  RaypipeCamera turned;
  turned.u = {r, 0, -r};
  turned.w = {r, 0, r};
  const KdRay ray = prgRay(turned, prgLevelSize(5), 1, 0);
  CHECK(bitsOf(ray.direction[0]) == 0xC25F721Cu);
  CHECK(ray.direction[1] == 239.0f);
  CHECK(bitsOf(ray.direction[2]) == 0x43C5A2E8u);
  // A denormal register entry is flushed before its product: 240 * 1e-40 would be 2.4e-38.
  RaypipeCamera tiny;
  tiny.w = {0, 0, 1e-40f};
  CHECK(prgRay(tiny, prgLevelSize(5), 320, 239).direction[2] == 0.0f);
  // Any other size keeps the 90-degree vertical field: 30x20 has pw = 24, half width 360.
  CHECK(direction(prgRay(reset, {30, 20}, 0, 0)) == std::array<float, 3>{-360, 216, 240});
  CHECK(primaryRays(reset, prgLevelSize(1)).size() == 1200);
}

TEST_CASE("rtusim's camera as the seed's registers", "[raypipe][prg]") {
  Camera camera;
  camera.position = {-1.9, 1.3, -2.6};
  camera.lookAt = {0.5, 0.25, 0.0};
  camera.up = {0, 1, 0};
  camera.verticalFovDegrees = 60;
  const RaypipeCamera registers = raypipeCameraOf(camera);
  // E is the position in hardware space (x and y swapped).
  CHECK(registers.eye == std::array<float, 3>{1.3f, -1.9f, -2.6f});
  const auto world = [](const std::array<float, 3>& hardware) {
    return glm::dvec3(hardware[1], hardware[0], hardware[2]);
  };
  // U and V are unit; W's length is 1 / tan(30 degrees).
  CHECK(glm::length(world(registers.u)) == Approx(1).epsilon(1e-6));
  CHECK(glm::length(world(registers.v)) == Approx(1).epsilon(1e-6));
  CHECK(glm::length(world(registers.w)) == Approx(std::sqrt(3.0)).epsilon(1e-6));
  // The centre ray, x = 320, y_prg = 240 (row 239), points at the look-at point.
  const KdRay centre = prgRay(registers, prgLevelSize(5), 320, 239);
  const glm::dvec3 toTarget = glm::normalize(camera.lookAt - camera.position);
  const glm::dvec3 centreWorld = glm::normalize(world(centre.direction));
  CHECK(glm::length(centreWorld - toTarget) < 1e-6);
  // The top-left ray: the corner of the image plane at distance 1, 30 degrees up and
  // 4/3 tan(30) across, less one pixel row (the PRG's top row is y_prg = 479 of 480).
  const glm::dvec3 right = glm::normalize(glm::cross(toTarget, camera.up));
  const glm::dvec3 up = glm::cross(right, toTarget);
  const double half = std::tan(M_PI / 6);
  const glm::dvec3 corner =
      glm::normalize(toTarget - right * half * 4.0 / 3.0 + up * half * 239.0 / 240.0);
  const glm::dvec3 topLeft =
      glm::normalize(world(prgRay(registers, prgLevelSize(5), 0, 0).direction));
  CHECK(glm::length(topLeft - corner) < 1e-6);
  // And back: the nearest rtusim camera looks the same way with the same field.
  const Camera back = cameraOfRegisters(registers, 640, 480);
  CHECK(glm::length(back.position - camera.position) < 1e-6);
  CHECK(glm::length(glm::normalize(back.lookAt - back.position) - toTarget) < 1e-6);
  CHECK(glm::length(glm::normalize(back.up) - up) < 1e-6);
  CHECK(back.verticalFovDegrees == Approx(60).epsilon(1e-6));
  // Registers given are kept, the rest converted.
  RaypipeCameraSettings settings;
  settings.eye = std::array<float, 3>{1, 2, 3};
  const RaypipeCamera resolved = settings.resolve(camera);
  CHECK(resolved.eye == std::array<float, 3>{1, 2, 3});
  CHECK(resolved.w == registers.w);
}

}  // namespace rtu
