#include <catch2/catch.hpp>

#include <random>
#include <string>
#include <vector>

#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"
#include "kinds/svo/svo_validator.h"
#include "svo_descriptor.h"

namespace rtu {
namespace {

uint32_t negative(uint32_t distance) { return 0u - distance; }  // a far offset pointing back

// A chain of `links` descriptors, each the only non-leaf child of the one before, ending in a
// descriptor with one leaf.
std::vector<uint32_t> chain(size_t links) {
  std::vector<uint32_t> words(links, descriptor(false, 1, 0x01, 0x00));
  words.push_back(descriptor(false, 0, 0x01, 0x01));
  return words;
}

void requireFormatError(const SvoImage& image, uint32_t address, const std::string& problem,
                        const SvoLimits& limits = {}) {
  try {
    validateSvo(image, limits);
    FAIL("the malformed image was accepted");
  } catch (const SvoFormatError& error) {
    INFO(error.what());
    CHECK(error.address() == address);
    CHECK_THAT(error.what(), Catch::Contains("word " + std::to_string(address) + ":") &&
                                 Catch::Contains(problem));
  }
}

void requireSameCounts(const SvoReport& report, const SvoStats& stats) {
  CHECK(report.descriptors == stats.descriptors);
  CHECK(report.leaves == stats.leaves);
  CHECK(report.farPointers == stats.farPointers);
  CHECK(report.depth == stats.depth);
  CHECK(report.words == stats.words);
  CHECK(report.sharedDescriptors == 0);
}

// Solid octant 0 at density 1/2 and the rest at 1/16, all from a hash so no two subtrees are
// alike: octant 0's subtree alone is over 32767 words, so its siblings need far pointers, and a
// wrong pointer lands on a different voxel pattern.
class DenseFirstOctant : public VoxelSource {
 public:
  int depth() const override { return 7; }
  Occupancy classify(const OctreeNode& node) const override {
    if (node.level < depth()) return Occupancy::Mixed;
    const uint32_t half = 1u << (depth() - 1);
    const bool firstOctant = node.x < half && node.y < half && node.z < half;
    const uint32_t bits = (node.x * 73856093u) ^ (node.y * 19349663u) ^ (node.z * 83492791u);
    const uint32_t mixed = (bits ^ (bits >> 13)) * 0x5bd1e995u;
    const uint32_t roll = mixed >> 28;  // 0..15
    return (firstOctant ? roll < 8 : roll == 0) ? Occupancy::Full : Occupancy::Empty;
  }
};

struct Walk {
  bool solid = false;
  bool throughFarPointer = false;
};

// Finds a voxel by walking the image from the root, resolving every pointer by hand.
Walk walkToVoxel(const SvoImage& image, int depth, uint32_t x, uint32_t y, uint32_t z) {
  Walk walk;
  uint32_t address = image.root;
  for (int shift = depth - 1; shift >= 0; --shift) {
    const int slot = (x >> shift & 1) | (y >> shift & 1) << 1 | (z >> shift & 1) << 2;
    const uint32_t word = image.words.at(address);
    const uint32_t valid = word >> 8 & 0xFF;
    const uint32_t leaf = word & 0xFF;
    if ((valid >> slot & 1) == 0) return walk;
    if ((leaf >> slot & 1) != 0) {
      walk.solid = true;
      return walk;
    }
    const bool far = (word >> 31) != 0;
    const uint32_t pointer = word >> 16 & 0x7FFF;
    const uint32_t offset = far ? image.words.at(address + pointer) : pointer;
    walk.throughFarPointer |= far;
    const uint32_t siblingsBefore = valid & ~leaf & ((1u << slot) - 1);
    address = address + offset + static_cast<uint32_t>(__builtin_popcount(siblingsBefore));
  }
  FAIL("the walk went below the voxel level");
  return walk;
}

TEST_CASE("validator: images built from procedural scenes pass with the builder's counts",
          "[validator]") {
  for (const std::string& name : proceduralSceneNames()) {
    for (uint32_t rootAddress : {0u, 5u}) {
      INFO(name << ", root at " << rootAddress);
      const SvoBuild build = buildSvo(*makeProceduralScene(name, 6, 3), rootAddress);
      requireSameCounts(validateSvo(build.image), build.stats);
    }
  }
}

TEST_CASE("validator: an empty scene and a full scene pass", "[validator]") {
  const SvoReport empty = validateSvo(SvoImage{{descriptor(false, 0, 0x00, 0x00)}, 0});
  CHECK(empty.descriptors == 1);
  CHECK(empty.leaves == 0);
  CHECK(empty.depth == 0);

  const SvoReport full = validateSvo(SvoImage{{descriptor(false, 0, 0xFF, 0xFF)}, 0});
  CHECK(full.leaves == 8);
  CHECK(full.depth == 1);
}

TEST_CASE("validator: a far pointer, also one pointing backwards, is followed", "[validator]") {
  SECTION("forwards") {
    const SvoImage image{{descriptor(true, 1, 0x01, 0x00), 2, descriptor(false, 0, 0x0F, 0x0F)}, 0};
    const SvoReport report = validateSvo(image);
    CHECK(report.descriptors == 2);
    CHECK(report.farPointers == 1);
    CHECK(report.leaves == 4);
    CHECK(report.depth == 2);
  }
  SECTION("backwards, the offset added modulo 2^32") {
    const SvoImage image{
        {descriptor(false, 0, 0xFF, 0xFF), 0, descriptor(true, 1, 0x01, 0x00), negative(2)}, 2};
    const SvoReport report = validateSvo(image);
    CHECK(report.descriptors == 2);
    CHECK(report.farPointers == 1);
    CHECK(report.leaves == 8);
    CHECK(report.depth == 2);
  }
}

TEST_CASE("validator: a descriptor shared by two parents is legal and counted once",
          "[validator]") {
  const SvoImage image{{descriptor(false, 1, 0x03, 0x00), descriptor(false, 2, 0x01, 0x00),
                        descriptor(false, 1, 0x01, 0x00), descriptor(false, 0, 0x80, 0x80)},
                       0};
  const SvoReport report = validateSvo(image);
  CHECK(report.descriptors == 4);
  CHECK(report.sharedDescriptors == 1);
  CHECK(report.leaves == 1);
  CHECK(report.depth == 3);
  CHECK_THAT(describe(report), Catch::Contains("4 descriptors (1 shared)") &&
                                   Catch::Contains("1 leaves") && Catch::Contains("depth 3"));
}

TEST_CASE("validator: malformed images are rejected naming the word and the problem",
          "[validator]") {
  SECTION("root outside the image") {
    requireFormatError(SvoImage{{descriptor(false, 0, 0, 0)}, 1}, 1,
                       "root descriptor is outside the image of 1 words");
    requireFormatError(SvoImage{{}, 0}, 0, "root descriptor is outside the image of 0 words");
  }
  SECTION("child block outside the image") {
    requireFormatError(SvoImage{{descriptor(false, 1, 0x03, 0x00), 0}, 0}, 0,
                       "child pointer 1 puts the 2 non-leaf children at words 1..2, outside the "
                       "image of 2 words");
  }
  SECTION("far word outside the image") {
    requireFormatError(SvoImage{{0, descriptor(true, 5, 0x01, 0x00)}, 1}, 1,
                       "far pointer 5 names far word 6, outside the image of 2 words");
  }
  SECTION("far offset leading outside the image") {
    requireFormatError(SvoImage{{descriptor(true, 1, 0x01, 0x00), 100}, 0}, 0,
                       "far word 1 holds offset 100, which puts the 1 non-leaf children at words "
                       "100..100, outside");
    requireFormatError(SvoImage{{descriptor(true, 1, 0x01, 0x00), negative(1)}, 0}, 0,
                       "at words 4294967295..4294967295, outside");
  }
  SECTION("leaf bit on an invalid slot") {
    const SvoImage image{{descriptor(false, 1, 0x01, 0x00), descriptor(false, 0, 0x03, 0x05)}, 0};
    requireFormatError(image, 1,
                       "slot 2 is marked leaf but not valid (valid mask 0x03, leaf mask 0x05)");
  }
  SECTION("a descriptor that is its own child") {
    requireFormatError(SvoImage{{descriptor(false, 0, 0x01, 0x00)}, 0}, 0,
                       "cycle: the descriptor is reachable from itself (through the child "
                       "pointer of word 0)");
  }
  SECTION("a cycle through a far word, longer than the depth limit") {
    std::vector<uint32_t> words = chain(40);
    words.back() = descriptor(true, 1, 0x01, 0x00);
    words.push_back(negative(40));
    requireFormatError(SvoImage{words, 0}, 0, "cycle");
  }
  SECTION("valid children deeper than the limit") {
    requireFormatError(SvoImage{chain(12), 0}, 12,
                       "valid children at level 13, deeper than the maximum depth 12");
    requireFormatError(SvoImage{chain(3), 0}, 2, "at level 3, deeper than the maximum depth 2",
                       SvoLimits{2});
  }
}

TEST_CASE("validator: the depth limit is inclusive and the walk needs no call stack",
          "[validator]") {
  CHECK(validateSvo(SvoImage{chain(11), 0}).depth == 12);
  CHECK(validateSvo(SvoImage{chain(30), 0}, SvoLimits{31}).depth == 31);
  requireFormatError(SvoImage{chain(1000000), 0}, 12, "deeper than the maximum depth 12");
  CHECK_THROWS_AS(validateSvo(SvoImage{chain(1), 0}, SvoLimits{-1}), std::invalid_argument);
}

// The stack a tree needs counts descriptors, with or without leaves, and any number of roots cost
// one pass over the image.
TEST_CASE("validator: descriptor depth of many roots in one pass", "[validator]") {
  std::vector<uint32_t> leafless = chain(12);
  leafless.back() = descriptor(false, 0, 0x00, 0x00);  // no children at all
  const SvoReport report = validateSvo(SvoImage{leafless, 0});
  CHECK(report.depth == 0);
  CHECK(report.descriptorDepth == 12);
  CHECK(descriptorDepths(SvoImage{chain(30), 0}, {0, 5, 29, 30}) == std::vector<int>{30, 25, 1, 0});
  CHECK(descriptorDepths(SvoImage{chain(11), 0}, {0}) == std::vector<int>{11});

  // Every word of a million-link chain is a root: a walk per root would take 5e11 steps.
  const size_t links = 1000000;
  std::vector<uint32_t> roots(links + 1);
  for (uint32_t i = 0; i <= links; ++i)
    roots[i] = static_cast<uint32_t>(links - i);  // deepest last
  const std::vector<int> depths = descriptorDepths(SvoImage{chain(links), 0}, roots);
  REQUIRE(depths.size() == roots.size());
  for (size_t i = 0; i < roots.size(); ++i)
    REQUIRE(depths[i] == static_cast<int>(links - roots[i]));
  CHECK_THROWS_AS(descriptorDepths(SvoImage{chain(3), 0}, {0, 9}), SvoFormatError);
}

TEST_CASE("validator: far pointers written by the builder lead to the right children",
          "[validator]") {
  const DenseFirstOctant source;
  const SvoBuild build = buildSvo(source, 3);
  REQUIRE(build.stats.farPointers > 0);
  requireSameCounts(validateSvo(build.image), build.stats);

  std::mt19937 random(7);
  std::uniform_int_distribution<uint32_t> coordinate(0, (1u << source.depth()) - 1);
  size_t mismatches = 0;
  size_t throughFar = 0;
  for (int sample = 0; sample < 20000; ++sample) {
    const uint32_t x = coordinate(random), y = coordinate(random), z = coordinate(random);
    const Walk walk = walkToVoxel(build.image, source.depth(), x, y, z);
    const bool solid = source.classify(OctreeNode{source.depth(), x, y, z}) == Occupancy::Full;
    mismatches += walk.solid != solid;
    throughFar += walk.throughFarPointer;
  }
  CHECK(mismatches == 0);
  CHECK(throughFar > 10000);
}

// Mostly words that look like descriptors with sparse masks and short pointers, or like far
// offsets either way: they reach deeper into the checks than uniformly random words.
uint32_t randomWord(std::mt19937& random, uint32_t size) {
  const auto byte = [&] { return static_cast<uint8_t>(random()); };
  switch (random() % 8) {
    case 0: return static_cast<uint32_t>(random());
    case 1:
    case 2: return static_cast<uint32_t>(random() % (2 * size + 1)) - size;
    default: {
      const auto valid = static_cast<uint8_t>(byte() & byte());
      const auto leaf = static_cast<uint8_t>(random() % 16 == 0 ? byte() : valid & byte());
      const bool anywhere = random() % 4 == 0;
      const auto pointer = static_cast<uint32_t>(random() % (anywhere ? size + 2 : 8));
      return descriptor(random() % 8 == 0, pointer, valid, leaf);
    }
  }
}

TEST_CASE("validator: random images are accepted or rejected, never crash or hang", "[validator]") {
  std::mt19937 random(2024);
  size_t accepted = 0;
  size_t rejected = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    const uint32_t size = random() % 201;
    SvoImage image;
    for (uint32_t i = 0; i < size; ++i) image.words.push_back(randomWord(random, size));
    image.root = random() % (size + 3);
    const SvoLimits limits{static_cast<int>(random() % 5)};  // low, so depth errors occur too
    try {
      const SvoReport report = validateSvo(image, limits);
      CHECK(report.descriptors <= size);
      ++accepted;
    } catch (const SvoFormatError&) {
      ++rejected;
    }
  }
  CHECK(accepted > 100);
  CHECK(rejected > 100);
}

}  // namespace
}  // namespace rtu
