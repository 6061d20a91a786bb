#pragma once
// Seed 003's BVH node as words (Langr 2016, section 3.4, lines 700-716): 32 bytes, the box as six
// float32 values (min x, y, z, then max x, y, z: the seed does not print their order, reading
// B7), then two words: an inner node's left and right child indices, or a leaf's first index into
// the triangle reference array and its count. Bit 31 of the second word is 1 in a leaf, 0 in an
// inner node (cleared "using the 0x80000000 bit mask" before use). The traversal reads a node in
// two 4-word accesses: words 0-3 and 4-7.

#include <array>
#include <cstdint>

#include "base/float_bits.h"
#include "geometry/aabb.h"

namespace rtu {

struct LangrNode {
  static constexpr uint32_t kWords = 8;
  static constexpr uint32_t kLeafBit = 0x80000000u;
  using Words = std::array<uint32_t, kWords>;

  static Aabb<float> box(const Words& words) {
    Aabb<float> box;
    for (int k = 0; k < 3; ++k) {
      box.lower[k] = bitsToFloat(words[k]);
      box.upper[k] = bitsToFloat(words[3 + k]);
    }
    return box;
  }
  static bool leaf(const Words& words) { return (words[7] & kLeafBit) != 0; }
  // An inner node's children.
  static uint32_t left(const Words& words) { return words[6]; }
  static uint32_t right(const Words& words) { return words[7]; }
  // A leaf's triangles: references first .. first + count - 1.
  static uint32_t first(const Words& words) { return words[6]; }
  static uint32_t count(const Words& words) { return words[7] & ~kLeafBit; }
};

}  // namespace rtu
