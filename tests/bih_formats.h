#pragma once
// The small fixed-point format of the BIH hand cases: n = 4 (grid 0..15), m = 6 = n + 2 (so the
// VHDL kernel accepts it), E = 2, T = 0, C = 2. Directions and normals are at scale 2^5 = 32 (-32
// is -1 exactly, +1 saturates to 31), edges at scale 2^7 = 128 and clamped to ±31 codes.

#include "kinds/bih/fixed_format.h"

namespace rtu {

inline constexpr FixedTriangleFormat kFourBit{4, 6, 2, 0, 2, FixedListing::Vhdl};

// The BIH hand cases' grid, also n = 4, with arithmetic wide enough that their triangles' edges
// (1/3 to 1/7 of a unit) are neither clamped nor coarse: m = 16 (directions at scale 2^15), E = 1
// (edges at scale 2^16, clamped only at 1/2), C = 4, the C99 listing (idir = 2^20 / ω: a ray's
// BIH distances are twice its grid distances, and an axis it does not move along has 2^20).
inline constexpr FixedTriangleFormat kFourBitC99{4, 16, 1, 0, 4, FixedListing::C99};

// The same grid for the VHDL kernel, which needs m = n + 2 = 6 (directions at scale 2^5: -1 is
// -32, +1 saturates to 31): E = 1 puts the hand triangles' edges 1/3 .. 1/7 at scale 2^6 (21 .. 9
// codes) below the clamp at 1/2; C = 4 gives idir = trunc(2^9 / ω), -16 for a ray straight down,
// 511 (saturated) on an axis it does not move along, so axis-aligned distances are exact.
inline constexpr FixedTriangleFormat kFourBitVhdl{4, 6, 1, 0, 4, FixedListing::Vhdl};

}  // namespace rtu
