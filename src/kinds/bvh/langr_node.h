#pragma once
// Seed 003's node layout (bvh_image.h, BvhNode) as the traversal's layout policy: what a
// traversal that holds a node's 8 words asks of them, decoded inline on its per-state path. The
// traversal reads a node in two 4-word accesses: words 0-3 and 4-7.

#include <array>
#include <cstdint>

#include "base/float_bits.h"
#include "geometry/aabb.h"
#include "kinds/bvh/bvh_image.h"

namespace rtu {

struct LangrNode {
  static constexpr uint32_t kWords = kBvhNodeWords;
  using Words = std::array<uint32_t, kWords>;

  static Aabb<float> box(const Words& words) {
    Aabb<float> box;
    for (int k = 0; k < 3; ++k) {
      box.lower[k] = bitsToFloat(words[k]);
      box.upper[k] = bitsToFloat(words[3 + k]);
    }
    return box;
  }
  static bool leaf(const Words& words) { return (words[7] & kBvhLeafBit) != 0; }
  // An inner node's children.
  static uint32_t left(const Words& words) { return words[6]; }
  static uint32_t right(const Words& words) { return words[7]; }
  // A leaf's triangles: references first .. first + count - 1.
  static uint32_t first(const Words& words) { return words[6]; }
  static uint32_t count(const Words& words) { return words[7] & ~kBvhLeafBit; }
};

}  // namespace rtu
