// The shared header words of the triangle kinds' images (rtu/image_sections.h): placement after
// the 16-word header with the triangles on a 4-word boundary, the 32-bit size limit, the words'
// order, and the checks a validator draws from them.
#include <catch2/catch.hpp>

#include "rtu/image_sections.h"

namespace rtu {

TEST_CASE("Image sections: nodes after the header, the triangles on an access boundary",
          "[image_sections]") {
  ImageSections sections;
  std::string error;
  // 3 nodes of 8 words: the list at 16 + 24 = 40; 5 entries end at 45, the triangles start at
  // 48; 2 records of 12 words end the image at 72.
  REQUIRE(placeSections(3, 8, 5, 2, 12, sections, error));
  CHECK(sections.nodeBase == 16);
  CHECK(sections.listBase == 40);
  CHECK(sections.triangleBase == 48);
  CHECK(sections.totalWords == 72);
  CHECK((sections.nodeCount == 3 && sections.listCount == 5 && sections.triangleCount == 2));
  // 1 node puts the list and the triangles at 24; 2^28 records of 16 words end at 2^32 + 24.
  CHECK_FALSE(placeSections(1, 8, 0, uint64_t{1} << 28, 16, sections, error));
  CHECK(error == "4294967320 words, more than 4294967295 (word addresses have 32 bits)");
}

TEST_CASE("Image sections: words 0-10 in their order, read back", "[image_sections]") {
  ImageSections sections{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  uint32_t header[kImageHeaderWords] = {};
  writeSections(sections, header);
  for (uint32_t i = 0; i < kImageSectionWords; ++i) CHECK(header[i] == i + 1);
  CHECK(header[kImageSectionWords] == 0);
  const ImageSections back = readSections(header);
  CHECK((back.listBase == 7 && back.totalWords == 11));
}

TEST_CASE("Image sections: a misplaced section and a wrong size are named", "[image_sections]") {
  ImageSections placed;
  std::string error;
  REQUIRE(placeSections(1, 8, 1, 1, 12, placed, error));  // list at 24, triangles at 28, 40 words
  ImageSections found = placed;
  found.listBase = 25;
  ImageProblems problems("X");
  checkPlacement(found, placed, 41, "reference", problems);
  const std::vector<ImageProblem> list = problems.take();
  REQUIRE(list.size() == 2);
  CHECK(list[0].what == "X word 6: the header's reference base is 25, not 24");
  CHECK(list[1].what == "X word 10: the header says 40 words, the image has 41");
  CHECK(capacityExceeded(5, 5, "nodes", "why").empty());
  CHECK(capacityExceeded(6, 5, "nodes", "why") == "6 nodes, more than 5 (why)");
}

}  // namespace rtu
