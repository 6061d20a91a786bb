// Seed 001's unit-triangle matrices (kinds/kd/uttm.h) and scene file (kinds/kd/trayracer_scene.h):
// a matrix by hand word for word, node words by hand, round trips in both formats, the narrow
// format's limits and the hardware's capacities.
#include <catch2/catch.hpp>

#include <cmath>

#include "base/float_bits.h"
#include "kinds/kd/trayracer_scene.h"

namespace rtu {
namespace {

// A = (1, 0, 0), B = (0, 1, 0), C = 0: N = (C - A) x (B - A) = (-1, 0, 0) x (-1, 1, 0) = (0, 0,
// -1), so [A - C, B - C, N - C] = diag(1, 1, -1), det -1, and the inverse is diag(1, 1, -1) with t
// = 0. The zeros come out as -0: each off-diagonal cofactor, over all six products of the
// expansion, sums to +0, e.g. b12 = a12a34a43 + a13a32a44 + a14a33a42 - a12a33a44 - ... =
// (+0) + (+0) + (-0) - (-0) - (+0) - (+0) = +0 (the -0 products have the factor a33 = -1), and
// +0 times 1/det = -1 is -0. Fields (float24 = binary32 >> 8): 1 -> 3F8000, -1 -> BF8000,
// -0 -> 800000. Packed m00 m01 m02 m10 | m11 m12 m20 m21 | m22 tx ty tz, four fields per 3 words:
// [3F8000 80|0000 8000|00 800000].
TEST_CASE("UTTM of the unit triangle itself, word by word", "[kd]") {
  const UnitTriangleMatrix m = unitTriangleMatrix({1, 0, 0}, {0, 1, 0}, {0, 0, 0});
  CHECK(m.m[0][0] == 1.0);
  CHECK(m.m[2][2] == -1.0);
  const UttmWords words = packUttm(m);
  const UttmWords expected{0x3F800080u, 0x00008000u, 0x00800000u, 0x3F800080u, 0x00008000u,
                           0x00800000u, 0xBF800080u, 0x00008000u, 0x00800000u};
  CHECK(words == expected);
  const auto entries = unpackUttm(words);
  CHECK(entries[0] == 1.0f);
  CHECK(entries[4] == 1.0f);
  CHECK(entries[8] == -1.0f);
  CHECK(floatBits(entries[9]) == 0x80000000u);
}

// The transform maps A, B, C to (1,0,0), (0,1,0), 0 for any triangle (within double rounding).
TEST_CASE("UTTM maps a general triangle onto the unit triangle", "[kd]") {
  const glm::dvec3 a(0.3, -1.2, 2.0), b(1.7, 0.4, 1.1), c(-0.6, 0.9, 0.5);
  const UnitTriangleMatrix m = unitTriangleMatrix(a, b, c);
  const auto apply = [&m](const glm::dvec3& p) {
    glm::dvec3 q;
    for (int r = 0; r < 3; ++r) q[r] = m.m[r][0] * p.x + m.m[r][1] * p.y + m.m[r][2] * p.z + m.t[r];
    return q;
  };
  for (int k = 0; k < 3; ++k) {
    CHECK(apply(a)[k] == Approx(k == 0 ? 1.0 : 0.0).margin(1e-12));
    CHECK(apply(b)[k] == Approx(k == 1 ? 1.0 : 0.0).margin(1e-12));
    CHECK(apply(c)[k] == Approx(0.0).margin(1e-12));
  }
}

// A triangle in the plane x = 1 wound so that N = (C - A) x (B - A) = (0, 1, 0) x (0, 0, 1) =
// (1, 0, 0): its plane lies at distance 1 along N, so R1's third column N - C = (0, -1, 0) is A - C
// and B - C = (0, -1, 1) is in the plane too: det 0, 1/det infinite, every entry infinite or NaN,
// and INT never hits it (a voxel scene's outer faces on [-1, 1]^3). The `normal` column (N itself)
// gives det 1 and maps the triangle as any other, and C + N to (0, 0, 1).
TEST_CASE("UTTM of a triangle at distance 1: R1's singular\\, the normal column's not", "[kd]") {
  const glm::dvec3 a(1, 0, 0), b(1, 0, 1), c(1, 1, 0);
  const UnitTriangleMatrix r1 = unitTriangleMatrix(a, b, c);
  CHECK_FALSE(std::isfinite(r1.m[0][0]));
  CHECK_FALSE(std::isfinite(r1.t[2]));
  const UnitTriangleMatrix m = unitTriangleMatrix(a, b, c, KdMatrixColumn::Normal);
  const auto apply = [&m](const glm::dvec3& p) {
    glm::dvec3 q;
    for (int r = 0; r < 3; ++r) q[r] = m.m[r][0] * p.x + m.m[r][1] * p.y + m.m[r][2] * p.z + m.t[r];
    return q;
  };
  const glm::dvec3 expected[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {0, 0, 1}};
  const glm::dvec3 points[4] = {a, b, c, c + glm::dvec3(1, 0, 0)};
  for (int p = 0; p < 4; ++p)
    for (int k = 0; k < 3; ++k) CHECK(apply(points[p])[k] == Approx(expected[p][k]).margin(1e-12));
  CHECK(parseKdMatrixColumn("r1") == KdMatrixColumn::NormalMinusC);
  CHECK(parseKdMatrixColumn("normal") == KdMatrixColumn::Normal);
  CHECK_THROWS_WITH(parseKdMatrixColumn("n"), Catch::Contains("accel.kd_matrix 'n'"));
}

// Two triangles: T0 with x in [0, 1], T1 with x in [3, 4], both y, z in [0, 1].
std::vector<glm::dvec3> twoTriangles() {
  return {{0, 0, 0}, {1, 1, 0}, {0, 0, 1}, {3, 0, 0}, {4, 1, 0}, {3, 0, 1}};
}

// Root: d = (4, 1, 1), axis x (world), written as hardware axis 01. Edges S0 0 | E0 1 | S1 3 | E1
// 4: E0 at 1 (1, 1) costs 1 + 80 (6 + 14) / 18 = 89.9, S1 at 3 (1, 1) the same: E0, split 1.0
// (0x3F800000). 89.9 < 160 but n = 2 = maxTriangles... the root has 2 triangles: a leaf. So
// maxTriangles 1: root splits at 1, leaves [0] (node 1) and [1] (node 2).
// Root word: [47:46] 01, [45:18] 0x3F80000 (0x3F800000 >> 4), [17:2] 2, flags 0:
// 01 | 0011 1111 1000 0000 ... = 0x4000'0000'0000 | 0x3F80000 << 18 | 2 << 2 = 0x4FE000000008.
// Leaf 1: 11 | list 0 | count 1 << 24 = 0xC00001000000; leaf 2: 11 | list 1 << 30 | 1 << 24 =
// 0xC00041000000.
TEST_CASE("Tray Racer scene: node words by hand, round trips, both formats", "[kd]") {
  const std::vector<glm::dvec3> corners = twoTriangles();
  PbrtKdParameters parameters;
  parameters.maxTriangles = 1;
  const KdBuild build = buildPbrtKd(pbrtTriangleBoxes(corners), parameters);
  const TrayRacerScene scene =
      makeTrayRacerScene(build, corners, {{0, 0, 1}, {0, 0, -1}}, {{1, 0, 1}, 0.4});
  const std::vector<uint8_t> narrow = writeTrayRacerScene(scene, TrayRacerFormat::Narrow);
  // Sections: nodes 3 x 6 B = 18 B -> 5 words; lists 2 x 2 B -> 1 word; UTTM 18; colours 10; box 6;
  // plus 5 count words: 45 words.
  REQUIRE(narrow.size() == 45 * 4);
  const std::vector<uint8_t> head(narrow.begin(), narrow.begin() + 4 + 18);
  const std::vector<uint8_t> expected{0,    0,    0,    5,                  // 5 words of nodes
                                      0x4F, 0xE0, 0x00, 0x00, 0x00, 0x08,   // root
                                      0xC0, 0x00, 0x01, 0x00, 0x00, 0x00,   // leaf [0]
                                      0xC0, 0x00, 0x41, 0x00, 0x00, 0x00};  // leaf [1]
  CHECK(head == expected);
  // The box: hardware x = world y first: y_min 0, x_min 0, z_min 0, y_max 1, x_max 4, z_max 1.
  CHECK(scene.box == std::array<float, 6>{0, 0, 0, 1, 4, 1});
  // Colours of T0: ambient 1, 0, 1 (3F8000 000000 3F8000), normal 0, 0, 1, specular 0.4 =
  // 0x3ECCCCCD
  // -> 0x3ECC: bytes 3F 80 00 00 | 00 00 3F 80 | 00 00 00 00 | 00 00 00 3F | 80 00 3E CC.
  CHECK(scene.shades[0] ==
        TrayRacerShade{0x3F800000u, 0x00003F80u, 0x00000000u, 0x0000003Fu, 0x80003ECCu});
  for (TrayRacerFormat format : {TrayRacerFormat::Narrow, TrayRacerFormat::Wide}) {
    const std::vector<uint8_t> bytes = writeTrayRacerScene(scene, format);
    const TrayRacerScene back = readTrayRacerScene(bytes, format);
    CHECK(back.nodes == scene.nodes);
    CHECK(back.lists == scene.lists);
    CHECK(back.uttms == scene.uttms);
    CHECK(back.shades == scene.shades);
    CHECK(back.box == scene.box);
    CHECK(writeTrayRacerScene(back, format) == bytes);
  }
  CHECK(trayRacerCapacityWarnings(scene).empty());
}

TEST_CASE("Tray Racer scene: narrow limits refuse, capacities warn, corrupt files name the fault",
          "[kd]") {
  TrayRacerScene scene;
  TrayRacerNode leaf;
  leaf.leaf = true;
  leaf.count = 64;  // past the 6-bit field
  scene.nodes = {leaf};
  scene.lists.assign(64, 70000);  // past 16-bit ids
  CHECK_THROWS_WITH(writeTrayRacerScene(scene, TrayRacerFormat::Narrow),
                    Catch::Contains("leaf triangle count 64") && Catch::Contains("6-bit"));
  scene.nodes[0].count = 63;
  scene.lists.resize(63);
  CHECK_THROWS_WITH(writeTrayRacerScene(scene, TrayRacerFormat::Narrow),
                    Catch::Contains("triangle id 70000"));
  std::vector<uint8_t> truncated = writeTrayRacerScene(scene, TrayRacerFormat::Wide);
  truncated.resize(truncated.size() - 4);
  CHECK_THROWS_WITH(readTrayRacerScene(truncated, TrayRacerFormat::Wide),
                    Catch::Contains("box section"));
  scene.nodes.resize(4097, leaf);
  const std::vector<std::string> warnings = trayRacerCapacityWarnings(scene);
  REQUIRE(warnings.size() == 2);
  CHECK_THAT(warnings[0], Catch::Contains("4097 exceeds the Tray Racer's 4096"));
  CHECK_THAT(warnings[1], Catch::Contains("6-bit count"));
}

}  // namespace
}  // namespace rtu

namespace rtu {

TEST_CASE("Tray Racer scene: a shading record's normal reads back", "[kd]") {
  const std::vector<glm::dvec3> corners = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},
                                           {0, 0, 1}, {1, 0, 1}, {0, 1, 2}};
  const KdBuild build = buildPbrtKd(pbrtTriangleBoxes(corners), PbrtKdParameters{});
  // -0.6 and 0.8 straddle the record's word boundaries (bits 72-143 of 160).
  const std::vector<glm::dvec3> normals = {{0, 0, 1}, {-0.6, 0.8, 0.0}};
  const TrayRacerScene scene = makeTrayRacerScene(build, corners, normals, {glm::dvec3(0.5), 1});
  CHECK(trayRacerNormal(scene.shades[0]) == glm::dvec3(0, 0, 1));
  // float24 keeps 15 fraction bits, truncated: -0.6f = 0xBF19999A reads as 0xBF199900.
  const glm::dvec3 n = trayRacerNormal(scene.shades[1]);
  CHECK(n.x == static_cast<double>(bitsToFloat(0xBF199900u)));
  CHECK(n.y == static_cast<double>(bitsToFloat(0x3F4CCC00u)));  // 0.8f = 0x3F4CCCCD
  CHECK(n.z == 0.0);
}

}  // namespace rtu
