#pragma once
// The SVO image's words (thesis figure 4.6): node descriptors over the RTU's word memory
// (rtu/word_memory.h; a read outside the image returns 0, an empty descriptor).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "rtu/word_memory.h"

namespace rtu {

// Set bits of a byte (the RTL's get_ones_count). A table, because without -mpopcnt the
// builtin becomes a library call on the traversal's hot path.
inline uint32_t bitCount(uint8_t bits) {
  static constexpr struct Table {
    uint8_t counts[256];
    constexpr Table() : counts() {
      for (int i = 1; i < 256; ++i) counts[i] = static_cast<uint8_t>((i & 1) + counts[i >> 1]);
    }
  } table;
  return table.counts[bits];
}

// Field layout of a 32-bit node descriptor (thesis figure 4.6, appendix C.4).
struct Descriptor {
  uint32_t word = 0;

  static constexpr uint32_t kMaxPointer = 0x7FFF;

  bool far() const { return (word >> 31) != 0; }
  uint32_t childPointer() const { return (word >> 16) & kMaxPointer; }
  uint8_t validMask() const { return static_cast<uint8_t>(word >> 8); }
  uint8_t leafMask() const { return static_cast<uint8_t>(word); }
  uint8_t nonLeafMask() const { return validMask() & ~leafMask(); }

  // Descriptors of the children that are valid and not leaves come first in slot order; this is
  // the offset of `slot`'s descriptor from the first.
  uint32_t childOffset(int slot) const {
    return bitCount(static_cast<uint8_t>(nonLeafMask() & ((1u << slot) - 1)));
  }

  static Descriptor make(bool far, uint32_t pointer, uint8_t valid, uint8_t leaf) {
    return {(far ? 0x80000000u : 0u) | (pointer & kMaxPointer) << 16 |
            static_cast<uint32_t>(valid) << 8 | leaf};
  }
};

}  // namespace rtu
