#pragma once
// The small fixed-point format of the BIH hand cases: n = 4 (grid 0..15), m = 6 = n + 2 (so the
// VHDL kernel accepts it), E = 2, T = 0, C = 2. Directions and normals are at scale 2^5 = 32 (-32
// is -1 exactly, +1 saturates to 31), edges at scale 2^7 = 128 and clamped to ±31 codes.

#include "kinds/bih/fixed_format.h"

namespace rtu {

inline constexpr FixedFormat kFourBit{4, 6, 2, 0, 2, FixedListing::Vhdl};

}  // namespace rtu
