// .svo files: raw little-endian words, read back exactly as written.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "kinds/svo/golden_model.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"
#include "kinds/svo/svo_validator.h"

using namespace rtu;

namespace {

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("rtusim_test_" + name)).string();
}

}  // namespace

TEST_CASE("SVO images round-trip through .svo files", "[svo]") {
  const SvoBuild build = buildSvo(*makeProceduralScene("terrain", 7), 3);
  const std::string path = tempPath("terrain.svo");
  writeSvoFile(path, build.image);
  REQUIRE(std::filesystem::file_size(path) == build.stats.bytes());

  const SvoImage back = readSvoFile(path, 3);
  REQUIRE(back.words == build.image.words);
  REQUIRE(back.root == 3);
  REQUIRE(validateSvo(back).descriptors == build.stats.descriptors);

  // Little-endian on disk: the root descriptor's low byte (its leaf mask) comes first.
  std::ifstream in(path, std::ios::binary);
  in.seekg(3 * 4);
  unsigned char bytes[4];
  in.read(reinterpret_cast<char*>(bytes), 4);
  REQUIRE(bytes[0] == Descriptor{build.image.words[3]}.leafMask());
  REQUIRE(bytes[1] == Descriptor{build.image.words[3]}.validMask());
}

TEST_CASE("Unreadable .svo files are reported by name", "[svo]") {
  REQUIRE_THROWS_WITH(readSvoFile(tempPath("missing.svo")), Catch::Contains("cannot open"));
  const std::string path = tempPath("odd.svo");
  std::ofstream(path, std::ios::binary) << "abcde";
  REQUIRE_THROWS_WITH(readSvoFile(path), Catch::Contains("5 bytes") && Catch::Contains("odd.svo"));
}
