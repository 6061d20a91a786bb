#pragma once
// The memory image of a seed-004 BIH as 32-bit words, what a BIH core reads (Listing A.3 p.57ff,
// spec 004 §4.4; docs/triangles.md, "BIH (seed 004)"). Every section starts on a multiple of 4
// words, one 16-byte access:
//   header     16 words (BihHeader, word order as its fields)
//   nodes      4 words each, node a at nodeBase + 4a: the listing's triple data, clip0, clip1
//              (its RAM0-RAM2 at one address) and a zero pad (encodeNode)
//   list       1 word each: triangle numbers, indices into the triangles (RAM3's tri_num, 29
//              bits); zero words up to the next multiple of 4
//   triangles  12 words each, the projected records (projected_triangle.h toWords)
// The seed's block RAM holds 1K words per RAM with the traversal stack at 992-1023, so the seed
// image has at most 992 nodes and 992 list entries and a 10-bit index in node_data(12:3). The
// `Wide` index uses bits 31:3 for larger scenes; either way, exceeding the seed's capacity is a
// warning naming the limit.

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "kinds/bih/bih_builder.h"
#include "kinds/bih/fixed_format.h"
#include "kinds/bih/grid.h"
#include "kinds/bih/projected_triangle.h"
#include "rtu/image_sections.h"
#include "rtu/word_memory.h"

namespace rtu {

constexpr uint32_t kBihMagic = 0x48494252;  // the bytes "RBIH" in little-endian order
constexpr uint32_t kBihKind = 1;            // Listing A.3's node triple, padded to 4 words
constexpr uint32_t kBihVersion = 1;
constexpr uint32_t kBihHeaderWords = kImageHeaderWords;
constexpr uint32_t kBihNodeWords = 4;
constexpr uint32_t kBihTriangleWords = kProjectedTriangleWords;
constexpr uint32_t kBihLeafAxis = 3;             // node_data(1:0) = 11 (A.3 node_s)
constexpr uint32_t kBihWideFlag = 1;             // header flags bit 0: node indices in bits 31:3
constexpr uint32_t kBihSeedNodes = 992;          // the seed's RAM0-2 below the stack (A.3)
constexpr uint32_t kBihSeedEntries = 992;        // the seed's RAM3 below the stack
constexpr uint32_t kBihTriangleNumberBits = 29;  // tri_num(28 downto 0)

// How many bits of node_data hold a child index or list start, from bit 3 on.
enum class BihIndexWidth { Seed, Wide };  // 10 bits (12:3) as the listing, or 29 (31:3)

inline int indexBits(BihIndexWidth width) { return width == BihIndexWidth::Seed ? 10 : 29; }

// The header: the shared sections (rtu/image_sections.h, words 0-10; the triangle numbers are the
// list; flags kBihWideFlag or 0) with this format's magic, kind and version, then words 11-14
// below; word 15 is 0.
struct BihHeader : ImageSections {
  BihHeader() {
    magic = kBihMagic;
    kind = kBihKind;
    version = kBihVersion;
  }
  uint32_t upperX = 0, upperY = 0, upperZ = 0;  // the scene box on the grid, [0, upper] (C15)
  uint32_t format = 0;                          // the records' FixedTriangleFormat (encodeFormat)

  BihIndexWidth width() const {
    return (flags & kBihWideFlag) != 0 ? BihIndexWidth::Wide : BihIndexWidth::Seed;
  }
  GridPoint sceneUpper() const { return {upperX, upperY, upperZ}; }
};

// A node as its words hold it. Inner: axis 0-2, index = the left child c (the right is c + 1),
// clip0 = the left child's upper bound, clip1 = the right child's lower bound. Leaf: axis 3,
// index = its first list entry, clip0 = its triangle count, clip1 = 0. node_data's bit 2 and the
// bits above the index are 0.
struct BihNode {
  uint32_t axis = 0;
  uint32_t index = 0;
  uint32_t clip0 = 0, clip1 = 0;

  bool leaf() const { return axis == kBihLeafAxis; }
  uint32_t count() const { return clip0; }
};

struct BihImage {
  std::vector<uint32_t> words;
  std::vector<std::string> warnings;  // the seed's capacities exceeded (bihCapacityWarnings)

  WordMemory memory() const { return WordMemory(words); }
  size_t bytes() const { return words.size() * sizeof(uint32_t); }
};

// What the image cannot hold at all: an index beyond its width, a triangle number beyond 29 bits,
// more than 2^32 - 1 words.
class BihCapacityError : public std::length_error {
 public:
  explicit BihCapacityError(const std::string& problem)
      : std::length_error("BIH image: " + problem) {}
};

// The header of an image with these counts, its sections placed as above. Throws
// BihCapacityError when they do not fit, or for a tree without a root.
BihHeader bihSections(uint64_t nodes, uint64_t entries, uint64_t triangles, BihIndexWidth width);

// "N nodes, more than the seed's 992 ..." for each of the seed's capacities the image exceeds.
std::vector<std::string> bihCapacityWarnings(const BihHeader& header);

// The image of `build` over `projected`'s records, on `grid`. Throws BihCapacityError as
// bihSections.
BihImage layOut(const BihBuild& build, const ProjectedMesh& projected, const SceneGrid& grid,
                BihIndexWidth width = BihIndexWidth::Seed);

// n, m, E, T, C in 6-bit fields from bit 0 up, the listing in bit 30 (1 = Vhdl).
uint32_t encodeFormat(const FixedTriangleFormat& format);
FixedTriangleFormat decodeFormat(uint32_t word);

std::array<uint32_t, kBihHeaderWords> encodeHeader(const BihHeader& header);
BihHeader decodeBihHeader(const uint32_t* words);  // from 16 words
std::array<uint32_t, kBihNodeWords> encodeNode(const BihNode& node, BihIndexWidth width);
BihNode decodeNode(const uint32_t* words, BihIndexWidth width);  // from 3 words

}  // namespace rtu
