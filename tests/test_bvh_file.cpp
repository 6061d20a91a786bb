// BVH image files (kinds/bvh/bvh_file.h): written and read back word for word, recognised by the
// header's magic, and refused with the validator's problems when unsound.
#include <catch2/catch.hpp>

#include "base/binary_file.h"
#include "bvh_meshes.h"
#include "kinds/bvh/bvh_file.h"
#include "kinds/bvh/bvh_validator.h"
#include "kinds/bvh/langr_builder.h"
#include "temp_path.h"

namespace rtu {

TEST_CASE("BVH files: written and read back word for word", "[bvh_file]") {
  const TriangleMesh mesh = rowOfTriangles(12);
  const BvhImage image = layOut(buildLangr(mesh).tree, mesh);
  const TempPath path("row.bvh");
  writeBvhFile(path.str(), image);
  CHECK(readBvhFile(path.str()).words == image.words);
  CHECK(looksLikeBvhImage(image.words));
  CHECK_FALSE(looksLikeBvhImage({}));
  CHECK_FALSE(looksLikeBvhImage({0x12345678}));
}

TEST_CASE("BVH files: an unsound image is refused naming the file and its problems", "[bvh_file]") {
  const TriangleMesh mesh = rowOfTriangles(12);
  BvhImage image = layOut(buildLangr(mesh).tree, mesh);
  const uint32_t root = decodeHeader(image.words.data()).nodeBase;
  image.words[root + 6] = 2;  // the root's left child made its right one
  const TempPath path("corrupt.bvh");
  writeBvhFile(path.str(), image);
  try {
    readBvhFile(path.str());
    FAIL("a corrupt image was read");
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    CHECK(message.rfind("BVH image '" + path.str() + "' is not a sound BVH image:\n  BVH word",
                        0) == 0);
    CHECK(message.find("child 2") != std::string::npos);
  }
}

TEST_CASE("BVH files: at most the first problems are listed", "[bvh_file]") {
  std::vector<BvhProblem> problems;
  for (uint32_t i = 0; i < 12; ++i) problems.push_back({i, "problem " + std::to_string(i)});
  const std::string message = describeBvhProblems("x.bvh", problems, 2);
  CHECK(message == "x.bvh is not a sound BVH image:\n  problem 0\n  problem 1\n  ...");
}

}  // namespace rtu
