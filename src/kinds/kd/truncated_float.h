#pragma once
// The reduced-width floats of seed 001's scene file (S1 §3.3.2-3.3.3 L411-427; R1
// SOFTWARE/src/scene/kdtree.cpp dump_uttm, dump_colors_and_normals): the high bits of a binary32,
// the low bits dropped (truncation toward zero, not rounding), and padded with zero bits back to a
// binary32 when the hardware reads them (specs/001 §4.7). float24 (1/8/15) holds the unit-triangle
// matrices and colours, float16 (1/8/7) the specular coefficient. The 28-bit split of a k-d node
// is the same rule with 4 bits dropped (kd_node.h).

#include <cstdint>

#include "base/float_bits.h"

namespace rtu {

// The top `bits` bits of x's binary32 pattern, right-aligned.
inline uint32_t truncatedBits(float x, int bits) { return floatBits(x) >> (32 - bits); }

// The binary32 whose top `bits` bits are `field` and whose other bits are zero.
inline float paddedFloat(uint32_t field, int bits) { return bitsToFloat(field << (32 - bits)); }

constexpr int kFloat24Bits = 24;
constexpr int kFloat16Bits = 16;

}  // namespace rtu
