// Seed 001's binary32 arithmetic (kinds/kd/binary32.h) and its truncated storage floats
// (kinds/kd/truncated_float.h) on IEEE edge cases, every expected value by hand: powers of two
// (exact), ties of round-to-nearest-even, denormals in and out, signed zeros, NaN, division by
// zero, and 1/3, whose binary expansion 0.010101... makes RNE round up and truncation down.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "base/float_bits.h"
#include "kinds/kd/binary32.h"
#include "kinds/kd/truncated_float.h"

namespace rtu {
namespace {

const float kDenormal = std::ldexp(1.0f, -140);  // below FLT_MIN = 2^-126
const float kNaN = std::numeric_limits<float>::quiet_NaN();

TEST_CASE("binary32: denormal inputs and results flush to a zero of their sign", "[kd]") {
  CHECK(floatBits(flushToZero(kDenormal)) == 0x00000000u);
  CHECK(floatBits(flushToZero(-kDenormal)) == 0x80000000u);
  CHECK(flushToZero(std::numeric_limits<float>::min()) == std::numeric_limits<float>::min());
  // 2^-140 * 2^100 is 2^-40 in IEEE; the flushed input makes it 0.
  CHECK(mul32(kDenormal, std::ldexp(1.0f, 100)) == 0.0f);
  // 2^-100 * 2^-30 = 2^-130 is denormal: +0, and -0 from a negative operand.
  CHECK(floatBits(mul32(std::ldexp(1.0f, -100), std::ldexp(1.0f, -30))) == 0x00000000u);
  CHECK(floatBits(mul32(-std::ldexp(1.0f, -100), std::ldexp(1.0f, -30))) == 0x80000000u);
  // 1.5 * 2^-126 - 2^-126 = 2^-127, denormal.
  CHECK(sub32(1.5f * std::ldexp(1.0f, -126), std::ldexp(1.0f, -126)) == 0.0f);
  CHECK(add32(kDenormal, kDenormal) == 0.0f);  // IEEE: 2^-139
}

TEST_CASE("binary32: sums round to nearest, ties to even", "[kd]") {
  const float half = std::ldexp(1.0f, -24);                           // half an ulp of 1
  CHECK(add32(1.0f, half) == 1.0f);                                   // tie: 1 is even
  CHECK(add32(1.0f + 2 * half, half) == 1.0f + 4 * half);             // tie: up to even
  CHECK(add32(1.0f, 1.5f * half) == 1.0f + 2 * half);                 // above the tie
  CHECK(mul32(1.0f + 2 * half, 1.0f + 2 * half) == 1.0f + 4 * half);  // 1 + 2^-22 + 2^-46
}

TEST_CASE("binary32: compares treat -0 as +0 and are false with NaN", "[kd]") {
  CHECK_FALSE(greater32(0.0f, -0.0f));
  CHECK_FALSE(greater32(-0.0f, 0.0f));
  CHECK(greaterEqual32(-0.0f, 0.0f));
  CHECK_FALSE(greater32(kNaN, 1.0f));
  CHECK_FALSE(greater32(1.0f, kNaN));
  CHECK_FALSE(greaterEqual32(kNaN, kNaN));
  CHECK_FALSE(greater32(kDenormal, 0.0f));  // flushed: equal
  CHECK(greater32(std::numeric_limits<float>::min(), 0.0f));
  CHECK(signBit32(-0.0f));
  CHECK(signBit32(-kDenormal));
  CHECK_FALSE(signBit32(kDenormal));
}

TEST_CASE("binary32: division by zero, by a denormal, and rounding of the quotient", "[kd]") {
  const Quotient one = div32(1.0f, 0.0f, Division::Ieee);
  CHECK(one.value == std::numeric_limits<float>::infinity());
  CHECK(one.divisionByZero);
  CHECK(div32(1.0f, -0.0f, Division::Ieee).value == -std::numeric_limits<float>::infinity());
  CHECK(div32(-1.0f, kDenormal, Division::Ieee).value == -std::numeric_limits<float>::infinity());
  CHECK(div32(-1.0f, kDenormal, Division::Ieee).divisionByZero);
  const Quotient nan = div32(0.0f, 0.0f, Division::Ieee);
  CHECK(std::isnan(nan.value));
  CHECK(nan.divisionByZero);
  CHECK_FALSE(div32(1.0f, 2.0f, Division::Ieee).divisionByZero);
  // 2^-100 / 2^30 = 2^-130: flushed.
  CHECK(div32(std::ldexp(1.0f, -100), std::ldexp(1.0f, 30), Division::Ieee).value == 0.0f);
  // 1/3 = 1.0101...b x 2^-2: 23 fraction bits 0101...010, then 1010... > half: RNE rounds up to
  // 0x3EAAAAAB; truncation keeps 0x3EAAAAAA. The same for 2/3 (exponent one higher) and -1/3.
  CHECK(floatBits(div32(1.0f, 3.0f, Division::Ieee).value) == 0x3EAAAAABu);
  CHECK(floatBits(div32(1.0f, 3.0f, Division::TowardZero).value) == 0x3EAAAAAAu);
  CHECK(floatBits(div32(2.0f, 3.0f, Division::TowardZero).value) == 0x3F2AAAAAu);
  CHECK(floatBits(div32(-1.0f, 3.0f, Division::TowardZero).value) == 0xBEAAAAAAu);
  // An exact quotient is the same either way; infinities stay.
  CHECK(div32(1.0f, 4.0f, Division::TowardZero).value == 0.25f);
  CHECK(div32(1.0f, 0.0f, Division::TowardZero).value == std::numeric_limits<float>::infinity());
}

TEST_CASE("truncated floats keep the high bits and pad with zeros", "[kd]") {
  // 1/3 = 0x3EAAAAAB: float24 keeps 0x3EAAAA (the low byte 0xAB dropped, toward zero), float16
  // 0x3EAA; 28 bits 0x3EAAAAA.
  const float third = bitsToFloat(0x3EAAAAABu);
  CHECK(truncatedBits(third, kFloat24Bits) == 0x3EAAAAu);
  CHECK(truncatedBits(third, kFloat16Bits) == 0x3EAAu);
  CHECK(truncatedBits(third, 28) == 0x3EAAAAAu);
  CHECK(floatBits(paddedFloat(0x3EAAAAu, kFloat24Bits)) == 0x3EAAAA00u);
  CHECK(truncatedBits(-2.0f, kFloat24Bits) == 0xC00000u);
  CHECK(paddedFloat(0xC00000u, kFloat24Bits) == -2.0f);
}

}  // namespace
}  // namespace rtu
