// The BVH image validator (kinds/bvh/bvh_validator.h): sound images pass, and each kind of
// corruption is found at the word derived by hand, naming the node, reference or triangle.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "base/float_bits.h"
#include "bvh_meshes.h"
#include "kinds/bvh/bvh_image.h"
#include "kinds/bvh/bvh_validator.h"
#include "kinds/bvh/langr_builder.h"

namespace rtu {
namespace {

// The 12-triangle row of test_bvh_image.cpp: nodes at words 16, 24, 32 (root, leaf of
// references 0-5, leaf of 6-11), references at 40 (0, 1, 3, 5, 8, 10, 11, 9, 7, 6, 4, 2),
// triangles at 52, 12 words each; triangle t is centred on x = 5, 0, 11, 3, 8, 1, 10, 6, 2, 9,
// 4, 7 (t = 0..11).
std::vector<uint32_t> rowWords() {
  const TriangleMesh mesh = rowOfTriangles({5, 0, 11, 3, 8, 1, 10, 6, 2, 9, 4, 7});
  return layOut(buildLangr(mesh).tree, mesh).words;
}

std::vector<uint32_t> problemWords(const std::vector<BvhProblem>& problems) {
  std::vector<uint32_t> words;
  for (const BvhProblem& problem : problems) words.push_back(problem.word);
  return words;
}

std::string allProblems(const std::vector<BvhProblem>& problems) {
  std::string text;
  for (const BvhProblem& problem : problems) text += problem.what + "\n";
  return text;
}

uint64_t fnv1a(const std::vector<uint32_t>& words) {
  uint64_t hash = 0xcbf29ce484222325;
  for (uint32_t word : words)
    for (int byte = 0; byte < 4; ++byte) {
      hash ^= (word >> (8 * byte)) & 0xFF;
      hash *= 0x100000001b3;
    }
  return hash;
}

}  // namespace

TEST_CASE("BVH validator: the row's image is sound", "[bvh]") {
  CHECK(validateBvh(rowWords()).empty());
}

TEST_CASE("BVH validator: each corruption of the row's image, at its word", "[bvh]") {
  std::vector<uint32_t> words = rowWords();
  SECTION("root's right child pointing at its left") {
    words[23] = 1;
    const auto problems = validateBvh(words);
    INFO(allProblems(problems));
    REQUIRE(problems.size() >= 2);
    CHECK(problems[0].word == 23);
    CHECK_THAT(problems[0].what,
               Catch::Contains("BVH word 23: node 0: child 1 is reached a second time"));
    CHECK(problems[1].word == 32);
    CHECK_THAT(problems[1].what, Catch::Contains("node 2 is reached from no parent"));
    // references 6-11 are then in no leaf and triangles 11, 9, 7, 6, 4, 2 referenced by none
    CHECK(problems.size() == 2 + 6 + 6);
  }
  SECTION("a child index outside the nodes") {
    words[22] = 7;
    const auto problems = validateBvh(words);
    REQUIRE_FALSE(problems.empty());
    CHECK(problems[0].word == 22);
    CHECK_THAT(problems[0].what, Catch::Contains("node 0: child 7 is outside the 3 nodes"));
  }
  SECTION("a leaf's box shrunk below its triangle") {
    words[27] = floatBits(5.0f);  // node 1's max x; triangle 0 reaches 5.5
    const auto problems = validateBvh(words);
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].word == 24);
    CHECK_THAT(problems[0].what, Catch::Contains("node 1: its box does not enclose triangle 0"));
  }
  SECTION("an inner box shrunk below its child's") {
    words[19] = floatBits(11.0f);  // the root's max x; node 2 reaches 11.5
    const auto problems = validateBvh(words);
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].word == 16);
    CHECK_THAT(problems[0].what, Catch::Contains("node 0: its box does not enclose child 2's"));
  }
  SECTION("a reference dropped: reference 5 (triangle 10) overwritten by triangle 11") {
    words[45] = 11;
    const auto problems = validateBvh(words);
    INFO(allProblems(problems));
    CHECK(problemWords(problems) == std::vector<uint32_t>{24, 52 + 12 * 10, 52 + 12 * 11});
    CHECK_THAT(problems[0].what, Catch::Contains("node 1: its box does not enclose triangle 11"));
    CHECK_THAT(problems[1].what, Catch::Contains("triangle 10 is referenced by 0 leaf entries"));
    CHECK_THAT(problems[2].what, Catch::Contains("triangle 11 is referenced by 2 leaf entries"));
  }
  SECTION("a leaf bit cleared: node 1 then names nodes 0 and 6") {
    words[31] = 6;
    const auto problems = validateBvh(words);
    REQUIRE(problems.size() >= 2);
    CHECK(problemWords(problems)[0] == 30);
    CHECK(problemWords(problems)[1] == 31);
  }
  SECTION("a leaf's range beyond the references") {
    words[39] = 0x80000007;  // node 2: 6..12 of 12
    const auto problems = validateBvh(words);
    REQUIRE_FALSE(problems.empty());
    CHECK(problems[0].word == 39);
    CHECK_THAT(problems[0].what, Catch::Contains("node 2: its references 6 to 12 go beyond"));
  }
  SECTION("a triangle's id and padding") {
    words[52 + 9] = 3;
    words[52 + 12 + 11] = 1;
    CHECK(problemWords(validateBvh(words)) == std::vector<uint32_t>{61, 74});
  }
  SECTION("the header") {
    words[0] = 0;
    words[8] = 56;
    words[13] = 1;
    const auto problems = validateBvh(words);
    CHECK(problemWords(problems) == std::vector<uint32_t>{0, 13, 8});
    CHECK_THAT(problems[0].what, Catch::Contains("magic is 0, not 1213612626"));
  }
  SECTION("the image cut short") {
    words.pop_back();
    const auto problems = validateBvh(words);
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].what == "BVH word 10: the header says 196 words, the image has 195");
    CHECK(problemWords(validateBvh({1, 2, 3})) == std::vector<uint32_t>{0});
  }
  SECTION("counts that do not fit") {
    words[5] = 0xFFFFFFFF;
    const auto problems = validateBvh(words);
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].word == 5);
  }
}

TEST_CASE("BVH validator: problems are listed up to a limit", "[bvh]") {
  std::vector<uint32_t> words = rowWords();
  for (size_t t = 0; t < 12; ++t) words[52 + 12 * t + 10] = 1;  // 12 problems
  CHECK(validateBvh(words).size() == 12);
  const TriangleMesh& mesh = assimpObjModel("spider.obj");
  std::vector<uint32_t> spider = layOut(buildLangr(mesh).tree, mesh).words;
  const uint32_t triangleBase = spider[8];
  for (size_t t = 0; t < mesh.triangles.size(); ++t) spider[triangleBase + 12 * t + 11] = 1;
  const auto problems = validateBvh(spider);
  REQUIRE(problems.size() == kMaxBvhProblems + 1);
  CHECK_THAT(problems.back().what, Catch::Contains("the rest are not listed"));
}

// The images of two real meshes pass; the spider's words are pinned (a regression guard: any
// change to the builder or the layout shows here first).
TEST_CASE("BVH validator: spider and Wuson images are sound", "[bvh]") {
  const std::string name = GENERATE(as<std::string>{}, "spider.obj", "WusonOBJ.obj");
  INFO(name);
  const TriangleMesh& mesh = assimpObjModel(name);
  const BvhImage image = layOut(buildLangr(mesh).tree, mesh);
  const auto problems = validateBvh(image.words);
  INFO(allProblems(problems));
  CHECK(problems.empty());
  if (name == "spider.obj") CHECK(fnv1a(image.words) == 0x42276b3006b73ee9);
}

}  // namespace rtu
