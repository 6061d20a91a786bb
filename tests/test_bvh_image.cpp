// The BVH memory image (kinds/bvh/bvh_image.h): every word of a hand-built image, the outward
// rounding of boxes, the capacity limits and the view that reads the words back.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <vector>

#include "bvh_meshes.h"
#include "kinds/bvh/bvh_image.h"
#include "kinds/bvh/langr_builder.h"

namespace rtu {
namespace {

// float32 bit patterns.
constexpr uint32_t kMinusHalf = 0xBF000000, kOne = 0x3F800000, kFourAndHalf = 0x40900000,
                   kFiveAndHalf = 0x40B00000, kTenAndHalf = 0x41280000, kElevenAndHalf = 0x41380000;

// The 12-triangle row of test_langr_builder.cpp: 3 nodes, references 0, 1, 3, 5, 8, 10, 11, 9,
// 7, 6, 4, 2; triangle 0 is centred on x = 5 and triangle 2 on x = 11.
BvhImage rowImage() {
  const TriangleMesh mesh = rowOfTriangles({5, 0, 11, 3, 8, 1, 10, 6, 2, 9, 4, 7});
  return layOut(buildLangr(mesh).tree, mesh);
}

std::vector<uint32_t> wordsAt(const BvhImage& image, size_t first, size_t count) {
  return {image.words.begin() + first, image.words.begin() + first + count};
}

}  // namespace

// Header 16 words, nodes at 16 (3 x 8), references at 40 (12), triangles at 52 (a multiple of 4
// already; 12 x 12), 196 words in all.
TEST_CASE("BVH image: every word of the 12-triangle row", "[bvh]") {
  const BvhImage image = rowImage();
  REQUIRE(image.words.size() == 196);
  CHECK(image.bytes() == 784);
  CHECK(wordsAt(image, 0, 16) ==
        std::vector<uint32_t>{0x48564252, 1, 1, 0, 16, 3, 40, 12, 52, 12, 196, 0, 0, 0, 0, 0});
  // root: box [-1/2, 11.5] x [0, 1] x [0, 0]; children 1 and 2
  CHECK(wordsAt(image, 16, 8) ==
        std::vector<uint32_t>{kMinusHalf, 0, 0, kElevenAndHalf, kOne, 0, 1, 2});
  // leaves: 6 references from 0 and from 6, bit 31 set
  CHECK(wordsAt(image, 24, 8) ==
        std::vector<uint32_t>{kMinusHalf, 0, 0, kFiveAndHalf, kOne, 0, 0, 0x80000006});
  CHECK(wordsAt(image, 32, 8) ==
        std::vector<uint32_t>{kFiveAndHalf, 0, 0, kElevenAndHalf, kOne, 0, 6, 0x80000006});
  CHECK(wordsAt(image, 40, 12) == std::vector<uint32_t>{0, 1, 3, 5, 8, 10, 11, 9, 7, 6, 4, 2});
  // triangle 0: (4.5, 0, 0), (5.5, 0, 0), (4.5, 1, 0), source 0; triangle 2 around x = 11
  CHECK(wordsAt(image, 52, 12) == std::vector<uint32_t>{kFourAndHalf, 0, 0, kFiveAndHalf, 0, 0,
                                                        kFourAndHalf, kOne, 0, 0, 0, 0});
  CHECK(wordsAt(image, 52 + 24, 12) == std::vector<uint32_t>{kTenAndHalf, 0, 0, kElevenAndHalf, 0,
                                                             0, kTenAndHalf, kOne, 0, 2, 0, 0});
}

// 0.1 is 0x3DCCCCCD in float32 rounded to nearest, which lies above 0.1: a vertex keeps it, a
// box's lower bound steps down to 0x3DCCCCCC and its upper bound keeps it.
TEST_CASE("BVH image: boxes rounded outward, vertices to nearest", "[bvh]") {
  TriangleMesh mesh;
  mesh.vertices = {{0.1, 0.1, 0.1}, {1, 0.1, 0.1}, {0.1, 1, 0.1}};
  mesh.triangles = {{0, 1, 2}};
  const BvhImage image = layOut(buildLangr(mesh).tree, mesh);
  CHECK(wordsAt(image, 16, 8) == std::vector<uint32_t>{0x3DCCCCCC, 0x3DCCCCCC, 0x3DCCCCCC, kOne,
                                                       kOne, 0x3DCCCCCD, 0, 0x80000001});
  // references at 24 (1 word, padded to 28), the triangle at 28
  CHECK(wordsAt(image, 28, 3) == std::vector<uint32_t>{0x3DCCCCCD, 0x3DCCCCCD, 0x3DCCCCCD});
}

TEST_CASE("BVH image: sections and what does not fit", "[bvh]") {
  const BvhHeader header = bvhSections(3, 13, 2);  // references 40..52, padded to 56
  CHECK(header.nodeBase == 16);
  CHECK(header.listBase == 40);
  CHECK(header.triangleBase == 56);
  CHECK(header.totalWords == 56 + 24);
  const uint64_t two31 = uint64_t{1} << 31;
  CHECK_THROWS_WITH(bvhSections(two31 + 1, 0, 0), Catch::Contains("2147483649 nodes"));
  CHECK_THROWS_WITH(bvhSections(two31, 0, 0), Catch::Contains("words"));  // 2^34 + 16
  CHECK_THROWS_WITH(bvhSections(1, two31, 0), Catch::Contains("2147483648 references"));
  CHECK_THROWS_WITH(bvhSections(1, 0, 2 * two31 + 1), Catch::Contains("triangles"));
  CHECK_THROWS_WITH(bvhSections(0, 0, 0), Catch::Contains("root"));
  CHECK_THROWS_AS(bvhSections(1, 0, two31 / 6), BvhCapacityError);  // 2^32 words of triangles
  TriangleMesh mesh = rowOfTriangles(1);
  mesh.vertices[1].x = 1e39;
  CHECK_THROWS_WITH(layOut(buildLangr(mesh).tree, mesh), Catch::Contains("float32's range"));
}

TEST_CASE("BVH image: the view reads nodes, references and triangles back", "[bvh]") {
  const BvhImage image = rowImage();
  const BvhImageView view(image.words);
  CHECK(view.header().nodeCount == 3);
  const BvhNode root = view.node(0);
  CHECK_FALSE(root.leaf);
  CHECK(root.leftOrFirst == 1);
  CHECK(root.rightOrCount == 2);
  CHECK(root.box.lower == glm::vec3{-0.5f, 0, 0});
  CHECK(root.box.upper == glm::vec3{11.5f, 1, 0});
  const BvhNode right = view.node(2);
  CHECK(right.leaf);
  CHECK(right.leftOrFirst == 6);
  CHECK(right.rightOrCount == 6);
  CHECK(view.ref(6) == 11);
  const BvhTriangle triangle = view.triangle(2);
  CHECK(triangle.source == 2);
  CHECK(triangle.vertices[1] == glm::vec3{11.5f, 0, 0});
  CHECK(view.nodeAddress(2) == 32);
  CHECK(view.refAddress(6) == 46);
  CHECK(view.triangleAddress(2) == 76);
  CHECK_THROWS_WITH(view.node(3), Catch::Contains("node 3 of 3"));
  const std::vector<uint32_t> cut(image.words.begin(), image.words.end() - 1);
  CHECK_THROWS_WITH(BvhImageView(cut).triangle(11), Catch::Contains("beyond the image's 195"));
  CHECK_THROWS_AS(BvhImageView(std::vector<uint32_t>(15)), std::out_of_range);
  const auto leftWords = encodeNode(view.node(1));  // decoding loses nothing
  CHECK(std::vector<uint32_t>(leftWords.begin(), leftWords.end()) == wordsAt(image, 24, 8));
}

}  // namespace rtu
