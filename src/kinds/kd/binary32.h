#pragma once
// Seed 001's floating point as its ray pipe computes it: every unit is an Altera altfp megafunction
// built with DENORMAL_SUPPORT="NO" and round-to-nearest (R1 COMMON/altfp_*; S1 §2.6.8 L238-244
// says only "floating point"). So each operation flushes denormal inputs to zero, rounds the exact
// result to nearest even (the host's float32 arithmetic, no fused multiply-add), and flushes a
// denormal result to zero. A flushed value keeps its sign, so a product that underflows from a
// negative operand is -0, which the INT unit's sign tests see. Compares follow altfp_compare:
// -0 equals +0, and any compare with a NaN is false (C++'s own float compare).
//
// Division: `Ieee` is correctly rounded. The shipped 6-cycle divider (altfp_div) is not: simulating
// its netlist, 317 of 20,000 random quotients (1.6 %) came out one ulp smaller in magnitude
// (specs/001 §2.0, experiment A.1). `Altfp` is that divider's own algorithm (altfp_div.h), bit for
// bit, flags included (its division_by_zero is b zero with a finite and nonzero; 0 / 0 is NaN).
// `TowardZero` truncates the exact quotient instead: it errs in the same direction, at most one
// ulp, but in about half of all quotients, so it bounds the divider's effect.

#include <cmath>
#include <cstdint>
#include <limits>

#include "base/float_bits.h"
#include "kinds/kd/altfp_div.h"

namespace rtu {

enum class Division : uint8_t { Ieee, TowardZero, Altfp };

// x with a denormal replaced by a zero of its sign.
inline float flushToZero(float x) {
  return std::abs(x) < std::numeric_limits<float>::min() ? std::copysign(0.0f, x) : x;
}

// One rounded float32 operation each, on and to flushed values. The flush (a compare and a select
// on the result) also keeps the compiler from contracting a product into a fused multiply-add.
inline float add32(float a, float b) { return flushToZero(flushToZero(a) + flushToZero(b)); }
inline float sub32(float a, float b) { return flushToZero(flushToZero(a) - flushToZero(b)); }
inline float mul32(float a, float b) { return flushToZero(flushToZero(a) * flushToZero(b)); }

// A quotient with the divider's division_by_zero flag: a divisor that is zero once flushed (TRAV's
// d_eq_0, specs/001 §2.2).
struct Quotient {
  float value = 0;
  bool divisionByZero = false;
};

inline Quotient div32(float a, float b, Division division) {
  if (division == Division::Altfp) {  // flushes its inputs and result itself
    const AltfpQuotient q = altfpDivide(floatBits(a), floatBits(b));
    return Quotient{bitsToFloat(q.bits), q.divisionByZero};
  }
  a = flushToZero(a);
  b = flushToZero(b);
  float q = a / b;
  // The double quotient of two floats never rounds onto a float unless it is one (their exact
  // quotient is then representable), so comparing with it finds whether RNE went outward.
  if (division == Division::TowardZero && std::isfinite(q)) {
    const double exact = double(a) / double(b);
    if (std::abs(double(q)) > std::abs(exact)) q = std::nextafter(q, 0.0f);
  }
  return Quotient{flushToZero(q), b == 0};
}

// a > b as altfp_compare's agb: inputs flushed, -0 = +0, false with a NaN.
inline bool greater32(float a, float b) { return flushToZero(a) > flushToZero(b); }
// a >= b (agb | aeb).
inline bool greaterEqual32(float a, float b) { return flushToZero(a) >= flushToZero(b); }
// The sign bit of the flushed value: what the RTL tests as bit 31 (so -0 is negative).
inline bool signBit32(float a) { return std::signbit(flushToZero(a)); }

}  // namespace rtu
