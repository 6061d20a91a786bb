// The k-d core's memory image (kinds/kd/kd_image.h) of the hand scene (kd_hand_scene.h): the
// header and node words by hand, and the validator on it and on corrupted copies.
#include <catch2/catch.hpp>

#include "kd_hand_scene.h"

namespace rtu {

// 5 nodes of 2 words from word 16 end at 26, so the lists start at 28; 4 list words end at 32,
// where the UTTMs start; 4 UTTMs of 12 words end at 80.
TEST_CASE("k-d image: header, nodes, lists and UTTMs by hand", "[kd]") {
  const TrayRacerScene scene = handKdScene();
  const KdImage image = layOutKd(scene);
  const std::vector<uint32_t> header(image.words.begin(), image.words.begin() + 16);
  CHECK(header == std::vector<uint32_t>{0x444B4252, 1, 16, 5, 28, 4, 32, 4, 80, 0, 0, 0, 0,
                                        0x41000000, 0x40000000, 0x40000000});
  REQUIRE(image.words.size() == 80);
  // Node 0: split 4.0 (0x40800000); axis 0, high child 4 in bits 29:2, no empty child.
  CHECK(image.words[16] == 0x40800000);
  CHECK(image.words[17] == 4u << 2);
  // Node 3: a leaf of list index 1 and 2 triangles.
  CHECK(image.words[22] == 1);
  CHECK(image.words[23] == (3u << 30 | 2));
  CHECK(std::vector<uint32_t>(image.words.begin() + 28, image.words.begin() + 32) ==
        std::vector<uint32_t>{0, 1, 3, 2});
  // T2's 9 words then 3 zero words.
  for (int w = 0; w < 9; ++w) CHECK(image.words[32 + 24 + w] == scene.uttms[2][w]);
  CHECK(image.words[32 + 24 + 9] == 0);
  for (size_t i = 0; i < scene.nodes.size(); ++i)
    CHECK(decodeKdNode(&image.words[16 + 2 * i]) == scene.nodes[i]);
  CHECK(decodeKdHeader(image.words.data()).box == scene.box);
}

TEST_CASE("k-d image: the validator passes a sound image and names each corrupt word", "[kd]") {
  const KdImage image = layOutKd(handKdScene());
  CHECK(validateKd(image.words).empty());
  const auto problemWord = [&image](uint32_t word, uint32_t value) {
    std::vector<uint32_t> words = image.words;
    words[word] = value;
    const std::vector<ImageProblem> problems = validateKd(words);
    REQUIRE(problems.size() == 1);
    return problems[0].word;
  };
  CHECK(problemWord(0, 0x48564252) == 0);          // the BVH's magic
  CHECK(problemWord(4, 30) == 2);                  // lists moved
  CHECK(problemWord(17, 99u << 2) == 17);          // node 0's high child
  CHECK(problemWord(22, 3) == 22);                 // node 3's list runs past the lists
  CHECK(problemWord(17, 4u << 2 | 3) == 16);       // node 0: both children empty
  CHECK(problemWord(29, 4) == 29);                 // a list entry naming no triangle
  CHECK(problemWord(32 + 10, 1) == 32 + 10);       // T0's padding
  CHECK(problemWord(13, floatBits(-1.0f)) == 10);  // x max below x min
  std::vector<uint32_t> shortened(image.words.begin(), image.words.end() - 1);
  CHECK(validateKd(shortened).at(0).word == 8);
}

}  // namespace rtu
