// The BIH memory image (kinds/bih/bih_image.h), its validator and file form: the hand scene's
// image word by word (bih_hand_scene.h, leaves of one triangle; the tree of
// test_bih_builder.cpp), corruptions each reported naming its word, the seed's capacities, and
// spider's image.
#include <catch2/catch.hpp>

#include <fstream>

#include "bih_hand_scene.h"
#include "bvh_meshes.h"
#include "geometry/ray_sets.h"
#include "kinds/bih/bih_file.h"
#include "kinds/bih/bih_validator.h"
#include "temp_path.h"

namespace rtu {
namespace {

BihImage handImage(uint32_t leafSize = 1) {
  const TriangleMesh mesh = bihHandMesh();
  const SceneGrid grid(meshBounds(mesh), kFourBitC99);
  const ProjectedMesh projected = projectMesh(mesh, grid);
  const BihBuild build =
      buildBih(triangleBoxes(mesh, grid, projected), sceneUpper(grid), BihBuildSettings{leafSize});
  return layOut(build, projected, grid);
}

std::vector<uint32_t> slice(const std::vector<uint32_t>& words, size_t first, size_t count) {
  return std::vector<uint32_t>(words.begin() + first, words.begin() + first + count);
}

std::vector<uint32_t> problemWords(const std::vector<ImageProblem>& problems) {
  std::vector<uint32_t> words;
  for (const ImageProblem& problem : problems) words.push_back(problem.word);
  return words;
}

// The hand image's sections: 7 nodes at 16, so the list at 16 + 28 = 44, its 4 entries to 48,
// already a multiple of 4: the triangles at 48, 4 x 12 words, 96 words in all.
constexpr uint32_t kList = 44, kTriangles = 48;

}  // namespace

TEST_CASE("BIH image: the hand scene word by word", "[bih]") {
  const BihImage image = handImage();
  REQUIRE(image.words.size() == 96);
  CHECK(image.warnings.empty());
  // Format: n 4 | m 16 << 6 | E 1 << 12 | T 0 << 18 | C 4 << 24, C99 (bit 30 clear).
  const uint32_t format = 4 + (16u << 6) + (1u << 12) + (4u << 24);
  CHECK(slice(image.words, 0, 16) == std::vector<uint32_t>{kBihMagic, 1, 1, 0, 16, 7, kList, 4,
                                                           kTriangles, 4, 96, 15, 7, 3, format, 0});
  // Node words (data, clip0, clip1, pad); data = axis | index << 3, a leaf's axis 3.
  CHECK(slice(image.words, 16, 28) ==
        std::vector<uint32_t>{0 | 1 << 3, 9, 11, 0,  // root: x, children 1, 2
                              0 | 3 << 3, 6, 2,  0,  // node 1: x, children 3, 4
                              1 | 5 << 3, 4, 3,  0,  // node 2: y, children 5, 6
                              3 | 0 << 3, 1, 0,  0,  // leaves: entry t, 1 triangle
                              3 | 1 << 3, 1, 0,  0,  //
                              3 | 2 << 3, 1, 0,  0,  //
                              3 | 3 << 3, 1, 0,  0});
  CHECK(slice(image.words, kList, 4) == std::vector<uint32_t>{0, 1, 2, 3});
  // T1: normal (7, 0, 0) x (0, 7, 0) = (0, 0, 49), r = 2, p = x, q = y; d = 2 49 / 49 = 2;
  // pp, pq = 2, 0; np = nq = 0; e1 = (7, 0) / 49 at scale 2^16: 65536 / 7 = 9362.3 -> 9362.
  CHECK(slice(image.words, kTriangles + 12, 12) ==
        std::vector<uint32_t>{2, 0, 2, 2, 0, 0, 0, 9362, 0, 0, 9362, 1});
  CHECK(validateBih(image.words).empty());
}

TEST_CASE("BIH image: one leaf of four with the default leaf size", "[bih]") {
  const BihImage image = handImage(4);
  // 1 node at 16, the list at 20, the triangles at 24.
  CHECK(slice(image.words, 4, 7) == std::vector<uint32_t>{16, 1, 20, 4, 24, 4, 24 + 48});
  CHECK(slice(image.words, 16, 8) == std::vector<uint32_t>{3, 4, 0, 0, 0, 1, 2, 3});
  CHECK(validateBih(image.words).empty());
}

TEST_CASE("BIH validator: each corruption names its word", "[bih]") {
  std::vector<uint32_t> words = handImage().words;
  SECTION("magic") {
    words[0] = 0;
    CHECK(problemWords(validateBih(words)) == std::vector<uint32_t>{0});
  }
  SECTION("a leaf of zero triangles") {
    words[16 + 4 * 3 + 1] = 0;
    const auto problems = validateBih(words);
    CHECK(problemWords(problems) == std::vector<uint32_t>{29, kList, kTriangles});
    CHECK_THAT(problems[0].what, Catch::Contains("counter would wrap"));
  }
  SECTION("children beyond the nodes") {
    words[16 + 4] = 0 | 6 << 3;  // node 1's children 6 and 7 of 7 nodes
    const auto problems = validateBih(words);
    REQUIRE_FALSE(problems.empty());
    CHECK(problems[0].word == 20);
    CHECK_THAT(problems[0].what, Catch::Contains("not both among the 7 nodes"));
  }
  SECTION("bit 2, a pad word") {
    words[16] |= 4;
    words[16 + 4 * 2 + 3] = 1;
    CHECK(problemWords(validateBih(words)) == std::vector<uint32_t>{16, 27});
  }
  SECTION("a triangle number beyond the triangles") {
    words[kList + 2] = 4;
    CHECK(problemWords(validateBih(words)) ==
          std::vector<uint32_t>{kList + 2, kTriangles + 2 * 12});
  }
  SECTION("triangles listed in the wrong leaves") {
    std::swap(words[kList], words[kList + 2]);
    // Leaf 3's box is x <= 6 (left of the root and of node 1): T2's first vertex (11, 0) is not
    // in it. Leaf 5's is x >= 11, y <= 4: T0's (0, 0) is not.
    const auto problems = validateBih(words);
    CHECK(problemWords(problems) == std::vector<uint32_t>{16 + 4 * 5, 16 + 4 * 3});
    CHECK_THAT(problems[0].what, Catch::Contains("triangle 0's first vertex"));
  }
  SECTION("a wrong size") {
    words.push_back(0);
    CHECK(problemWords(validateBih(words)) == std::vector<uint32_t>{10});
  }
}

TEST_CASE("BIH image: the seed's capacities", "[bih]") {
  CHECK(bihCapacityWarnings(bihSections(992, 992, 10, BihIndexWidth::Seed)).empty());
  const auto warnings = bihCapacityWarnings(bihSections(993, 1024, 10, BihIndexWidth::Seed));
  REQUIRE(warnings.size() == 2);
  CHECK_THAT(warnings[0], Catch::Contains("993 nodes, more than the seed's 992"));
  CHECK_THAT(warnings[1], Catch::Contains("1024 list entries"));
  CHECK_THROWS_WITH(bihSections(1025, 1, 1, BihIndexWidth::Seed),
                    Catch::Contains("10-bit node indices"));
  CHECK(bihSections(1025, 1, 1, BihIndexWidth::Wide).flags == kBihWideFlag);
  // A 29-bit index in bits 31:3.
  CHECK(encodeNode(BihNode{2, (1u << 29) - 1, 5, 6}, BihIndexWidth::Wide)[0] == 0xFFFFFFFAu);
  CHECK(encodeNode(BihNode{2, 1023, 5, 6}, BihIndexWidth::Seed)[0] == (1023u << 3 | 2));
}

TEST_CASE("BIH image: spider needs the wide index and is sound with it", "[bih]") {
  const TriangleMesh& mesh = assimpObjModel("spider.obj");
  const SceneGrid grid(meshBounds(mesh), kC99Format);
  const ProjectedMesh projected = projectMesh(mesh, grid);
  const BihBuild build = buildBih(triangleBoxes(mesh, grid, projected), sceneUpper(grid));
  CHECK_THROWS_WITH(layOut(build, projected, grid),
                    Catch::Contains("1312 list entries, more than 1024"));
  const BihImage image = layOut(build, projected, grid, BihIndexWidth::Wide);
  CHECK(validateBih(image.words).empty());
  REQUIRE(image.warnings.size() == 1);  // 951 nodes fit; 1312 entries do not
  CHECK_THAT(image.warnings[0], Catch::Contains("1312 list entries, more than the seed's 992"));
  CHECK(decodeFormat(image.words[14]).n == 29);
}

TEST_CASE("BIH file: written and read back, a corrupt one refused", "[bih]") {
  const BihImage image = handImage();
  const TempPath path("hand.bih");
  writeBihFile(path.str(), image);
  CHECK(readBihFile(path.str()).words == image.words);
  CHECK(looksLikeBihImage(image.words));
  BihImage corrupt = image;
  corrupt.words[16 + 4 * 6 + 1] = 0;
  writeBihFile(path.str(), corrupt);
  CHECK_THROWS_WITH(readBihFile(path.str()),
                    Catch::Contains("is not a sound BIH image") && Catch::Contains("BIH word 41"));
}

}  // namespace rtu
