#pragma once
// The bit widths of seed 004's fixed-point ray tracing (S4 = seeds/004_ad38b106ad170843.txt,
// Hanika 2007): n, m, E, T and C, with the two parameter sets of the seed as named variants.
// Every quantity's format follows from them (docs/triangles.md, "Fixed point (seed 004)"):
//   vertices, pp, pq, origin  n-bit unsigned grid integers (S4 §2.1.2 p.25 L280)
//   d                         (n+3)-bit signed integer, no fraction (L281, §2.1.4 L299)
//   np, nq, direction ω       m-bit signed, scale 2^(m-1): [-1, 1) (L285)
//   e1p, e1q, e2p, e2q        m-bit signed, scale 2^(m-1+E): the open (-2^-E, 2^-E) (§2.1.3 L293)
//   idir                      (m+C)-bit signed, C fractional bits (§2.4 p.30 L415-419)

#include <cstdint>
#include <stdexcept>
#include <string>

namespace rtu {

// Which of the seed's two implementations a format follows: it fixes the inverse direction's
// scale (grid.h) and is the kernel that format is meant for (fixed_kernels.h).
enum class FixedListing { C99, Vhdl };

struct FixedTriangleFormat {
  int n = 29;  // grid bits
  int m = 32;  // vector bits
  int E = 10;  // edge shift: edges are clamped to (-2^-E, 2^-E)
  int T = 0;   // least significant bits dropped from t's numerator and denominator (S4 §2.2)
  int C = 16;  // fractional bits of the inverse direction
  FixedListing listing = FixedListing::C99;
};

// Plan reading C1: the text's C99 prototype has n = 32 - 3 = 29, m = 32, E = 10, T = 0 (S4 §2.1.4
// L299-301, §2.2 L354); it names no C for the C99 code (Fig. 2.9 sweeps it), so the hardware's 16
// is taken. The VHDL type-checks only with m = n + 2, so n = 30 (spec 004 §8.1); C = 16 from
// Listing A.3's 48-bit idir; E = 10 as in the text (edge_shift's value is not printed); T = 0
// (S4 §4.2 L673).
inline constexpr FixedTriangleFormat kC99Format{29, 32, 10, 0, 16, FixedListing::C99};
inline constexpr FixedTriangleFormat kVhdlFormat{30, 32, 10, 0, 16, FixedListing::Vhdl};

// Throws std::invalid_argument naming the parameter unless the widths fit rtusim's records and
// 64-bit intermediates: 1 <= n <= 30 (the origin n+1 bits, d n+3 bits), 2 <= m <= 32 (one word per
// code), 0 <= E <= 63 - m, 0 <= T <= m - 2, 0 <= C <= 62 - m. A Vhdl format must
// have m = n + 2 and T = 0: the listing's widths assume both (A.2, spec 004 §8.1).
inline void validateFixedTriangleFormat(const FixedTriangleFormat& f) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("fixed-point format: " + what);
  };
  require(f.n >= 1 && f.n <= 30, "n must be in [1, 30], is " + std::to_string(f.n));
  require(f.m >= 2 && f.m <= 32, "m must be in [2, 32], is " + std::to_string(f.m));
  require(f.E >= 0 && f.m - 1 + f.E <= 62, "E must be in [0, 63 - m], is " + std::to_string(f.E));
  require(f.T >= 0 && f.T < f.m - 1, "T must be in [0, m - 2], is " + std::to_string(f.T));
  require(f.C >= 0 && f.m + f.C <= 62, "C must be in [0, 62 - m], is " + std::to_string(f.C));
  if (f.listing == FixedListing::Vhdl) {
    require(f.m == f.n + 2, "the VHDL listing needs m = n + 2");
    require(f.T == 0, "the VHDL listing has no T (it is 0)");
  }
}

}  // namespace rtu
