#pragma once
// The memory image of a Tray Racer scene (trayracer_scene.h) as 32-bit words: what a k-d core
// reads. rtusim's layout, not the seed's (its caches hold each section in its own BRAM, specs/001
// §4.8); every section starts on a multiple of 4 words, one 16-byte access:
//   header  16 words (KdHeader, word order as its fields; the scene box in words 10-15, loaded
//           into the core's scene-box registers at job set-up, as the scene loader fills SINT's)
//   nodes   2 words each, node 0 the root, so a node never straddles an access:
//             interior: word 0 the split's binary32 bits as the scene holds them (a narrow file's
//                       truncated to 28 bits); word 1 [31:30] axis (0 x, 1 y, 2 z in hardware
//                       space), [29:2] the high child, [1] low child empty, [0] high child empty
//             leaf:     word 0 the list index; word 1 [31:30] 3, [29:0] the triangle count
//   lists   1 word each: triangle ids, leaves' lists in node order
//   UTTMs   12 words each: the 9 words of packed float24 entries (uttm.h), then 3 zero words
// Colours and normals are shading data and stay in the scene file.

#include <array>
#include <cstdint>
#include <vector>

#include "kinds/kd/trayracer_scene.h"
#include "rtu/image_problems.h"
#include "rtu/word_memory.h"

namespace rtu {

constexpr uint32_t kKdMagic = 0x444B4252;  // the bytes "RBKD" in little-endian order
constexpr uint32_t kKdVersion = 1;
constexpr uint32_t kKdHeaderWords = 16;
constexpr uint32_t kKdNodeWords = 2;
constexpr uint32_t kKdUttmWords = 12;
constexpr uint32_t kKdLeafAxis = 3;

// Header words 0-9 in this order, then the scene box (hardware x, y, z min then max).
struct KdHeader {
  uint32_t magic = kKdMagic;
  uint32_t version = kKdVersion;
  uint32_t nodeBase = 0, nodeCount = 0;
  uint32_t listBase = 0, listCount = 0;
  uint32_t uttmBase = 0, uttmCount = 0;
  uint32_t totalWords = 0;
  uint32_t flags = 0;  // none defined: 0
  std::array<float, 6> box{};
};

struct KdImage {
  std::vector<uint32_t> words;
  WordMemory memory() const { return WordMemory(words); }
};

// The image of `scene`. Throws std::length_error when a count does not fit its field (more than
// 2^28 nodes or 2^30 - 1 triangles in a leaf) or the image exceeds 2^32 - 1 words.
KdImage layOutKd(const TrayRacerScene& scene);

std::array<uint32_t, kKdHeaderWords> encodeKdHeader(const KdHeader& header);
KdHeader decodeKdHeader(const uint32_t* words);  // from 16 words
std::array<uint32_t, kKdNodeWords> encodeKdNode(const TrayRacerNode& node);
TrayRacerNode decodeKdNode(const uint32_t* words);  // from 2 words

// Every problem found, in the order found: a header that is not this format, whose sections are
// not where layOutKd places them for its counts, or whose size is not the image's (then nothing
// further is read); an inverted scene box; a child outside the nodes; a leaf's list beyond the
// lists; a list entry outside the triangles; a UTTM's padding words not zero. Empty for a sound
// image.
std::vector<ImageProblem> validateKd(const std::vector<uint32_t>& words);

}  // namespace rtu
