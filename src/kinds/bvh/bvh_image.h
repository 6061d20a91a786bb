#pragma once
// The memory image of a BVH in seed 003's node format (Langr 2016, section 3.4, lines 700-718),
// as 32-bit words: what a traversal core reads. Layout (docs/triangles.md, "BVH (seed 003,
// langr)"); every section starts on a multiple of 4 words, one 16-byte access:
//   header     16 words (BvhHeader: rtu/image_sections.h, then zeros)
//   nodes      8 words each, node 0 the root (encodeNode)
//   references 1 word each: the triangle reference array, indices into the triangles (L718);
//              zero words up to the next multiple of 4
//   triangles  12 words each, in the mesh's order (the seed never moves them, L718): v0, v1, v2
//              as float32 rounded to nearest from double (words 0-8), the source triangle's
//              index (word 9), 0 (words 10-11). The seed's vertex normals (section 3.2.4) are
//              shading data and stay out of the record.

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "geometry/aabb.h"
#include "geometry/triangle_mesh.h"
#include "kinds/bvh/build_tree.h"
#include "rtu/image_sections.h"
#include "rtu/word_memory.h"

namespace rtu {

constexpr uint32_t kBvhMagic = 0x48564252;  // the bytes "RBVH" in little-endian order
constexpr uint32_t kBvhKind = 1;            // a BVH of 8-word nodes with the leaf flag in bit 31
constexpr uint32_t kBvhVersion = 1;
constexpr uint32_t kBvhHeaderWords = kImageHeaderWords;
constexpr uint32_t kBvhNodeWords = 8;
constexpr uint32_t kBvhTriangleWords = 12;
constexpr uint32_t kBvhLeafBit = 0x80000000u;  // in node word 7 (L709)

// The header: the shared sections (rtu/image_sections.h, words 0-10; the references are the
// list) with this format's magic, kind and version; words 11-15 are 0.
struct BvhHeader : ImageSections {
  BvhHeader() {
    magic = kBvhMagic;
    kind = kBvhKind;
    version = kBvhVersion;
  }
};

// A node as its 8 words hold it. Words 0-5: box min x, y, z, max x, y, z as float32 (the seed
// leaves the order open: min then max, B7). Word 6: leftChild (inner) or firstPrim, the leaf's
// first index into the references. Word 7: bit 31 set for a leaf; bits 30:0 rightChild (inner)
// or numPrim. The seed allocates children in adjacent pairs, so rightChild = leftChild + 1, and
// keeps both words all the same.
struct BvhNode {
  Aabb<float> box;
  bool leaf = false;
  uint32_t leftOrFirst = 0;
  uint32_t rightOrCount = 0;  // below 2^31
};

struct BvhTriangle {
  std::array<glm::vec3, 3> vertices;
  uint32_t source = 0;  // word 9: the mesh triangle it was made from
};

struct BvhImage {
  std::vector<uint32_t> words;

  WordMemory memory() const { return WordMemory(words); }
  size_t bytes() const { return words.size() * sizeof(uint32_t); }
};

// What the image cannot hold: more nodes than 31 bits can index, more references than a leaf
// count of 31 bits or more triangles than a word can name, more than 2^32 - 1 words in all, or a
// vertex coordinate beyond float32's range.
class BvhCapacityError : public std::length_error {
 public:
  explicit BvhCapacityError(const std::string& problem)
      : std::length_error("BVH image: " + problem) {}
};

// The header of an image with these counts, its sections placed as above. Throws
// BvhCapacityError when they do not fit, or for a tree without a root.
BvhHeader bvhSections(uint64_t nodes, uint64_t refs, uint64_t triangles);

// The image of `tree` over `mesh`: node boxes rounded outward to float32 (geometry/aabb.h), so
// each encloses its double original and with it its triangles' float32 vertices. Throws
// BvhCapacityError as bvhSections, or when a vertex coordinate exceeds float32's range.
BvhImage layOut(const BuildTree& tree, const TriangleMesh& mesh);

// The image's header, nodes and references, with `triangles` records left zero: layOut fills them
// from a mesh; a two-level BVH's top level (two_level.h) has none, its references naming
// instances. Throws as bvhSections.
BvhImage layOutNodes(const BuildTree& tree, uint64_t triangles);

std::array<uint32_t, kBvhHeaderWords> encodeHeader(const BvhHeader& header);
BvhHeader decodeHeader(const uint32_t* words);  // from 16 words
std::array<uint32_t, kBvhNodeWords> encodeNode(const BvhNode& node);
BvhNode decodeNode(const uint32_t* words);  // from 8 words

// Reads an image word by word, as a traversal does; it checks only that what it reads lies
// inside the image and its section (bvh_validator.h checks the rest).
class BvhImageView {
 public:
  // Throws std::out_of_range when `words` is shorter than a header.
  explicit BvhImageView(const std::vector<uint32_t>& words);

  const BvhHeader& header() const { return header_; }
  // Each throws std::out_of_range for an index beyond its section or a record beyond the image.
  BvhNode node(uint32_t index) const;
  uint32_t ref(uint32_t index) const;
  BvhTriangle triangle(uint32_t index) const;

  // Word addresses, in 64 bits: a corrupt header's may lie beyond 32.
  uint64_t nodeAddress(uint32_t index) const {
    return header_.nodeBase + uint64_t{kBvhNodeWords} * index;
  }
  uint64_t refAddress(uint32_t index) const { return header_.listBase + uint64_t{index}; }
  uint64_t triangleAddress(uint32_t index) const {
    return header_.triangleBase + uint64_t{kBvhTriangleWords} * index;
  }

 private:
  const uint32_t* record(const char* section, uint32_t index, uint32_t count, uint64_t address,
                         uint32_t size) const;

  const std::vector<uint32_t>& words_;
  BvhHeader header_;
};

}  // namespace rtu
