#pragma once
// Exact integer rounding for seed 004's fixed point, each rule named once: the precompute rounds
// exact rationals half to even (plan reading C4), the kernels floor by arithmetic shifts and
// truncate by C division, and registers of the VHDL keep their low bits. 128-bit intermediates
// where a product of two codes with a grid value exceeds 64 bits (GCC's __int128).

#include <cstdint>

namespace rtu {

__extension__ typedef __int128 Int128;  // __extension__: -Wpedantic accepts the GCC type

inline Int128 pow2(int bits) { return Int128(1) << bits; }

// x / 2^bits rounded toward minus infinity: C's `>>` on a negative value as GCC defines it
// (arithmetic shift), here exactly, whatever the sign.
inline Int128 floorShift(Int128 x, int bits) {
  const Int128 unit = pow2(bits);
  const Int128 quotient = x / unit;  // toward zero
  return quotient * unit > x ? quotient - 1 : quotient;
}

// The nearest integer to num / den, halves to the even one. den != 0.
inline Int128 roundHalfEven(Int128 num, Int128 den) {
  if (den < 0) num = -num, den = -den;
  Int128 quotient = num / den, remainder = num % den;
  if (remainder < 0) quotient -= 1, remainder += den;  // now num = quotient den + remainder
  const Int128 twice = 2 * remainder;
  if (twice > den || (twice == den && quotient % 2 != 0)) quotient += 1;
  return quotient;
}

// The low `bits` bits of x as a two's-complement value: what a register of that width holds,
// and what GCC's conversion to a narrower signed type keeps (modulo 2^bits).
inline int64_t wrapSigned(Int128 x, int bits) {
  const Int128 modulus = pow2(bits);
  Int128 low = x % modulus;
  if (low < 0) low += modulus;
  return static_cast<int64_t>(low >= modulus / 2 ? low - modulus : low);
}

inline Int128 clampTo(Int128 x, Int128 lowest, Int128 highest) {
  return x < lowest ? lowest : (x > highest ? highest : x);
}

}  // namespace rtu
