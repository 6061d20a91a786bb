// Float-to-fixed conversion against a literal transcription of the RTL pipeline (appendix C.2.1).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "kinds/svo/fixed_point.h"
#include "kinds/svo/ray_setup.h"

using namespace rtu;

namespace {

// The five register stages of float_to_fixed with FX_PT_FRAC_BITS = 16, statement by statement,
// including the printed saturation branch.
uint32_t printedRtlFloatToFixed(uint32_t in) {
  struct Stage {
    bool sign, expSign;
    uint8_t exponent;
    uint64_t fraction;
  };
  const int fracBits = 16;
  Stage s1{};
  s1.expSign = false;
  s1.sign = in >> 31;
  s1.fraction = static_cast<uint64_t>(0x800000 | (in & 0x7FFFFF)) << 9;  // fraction[32-:24]
  const int32_t exponent = static_cast<int32_t>((in >> 23) & 0xFF) - 127;
  if (exponent >= 0) {
    s1.exponent = static_cast<uint8_t>(exponent);
  } else {
    s1.exponent = static_cast<uint8_t>(-exponent);
    s1.expSign = true;
  }
  if (exponent >= 31 - fracBits) {
    s1.exponent = 0;
    s1.sign = false;
    s1.fraction = (in >> 31) ? uint64_t{1} << 63 : 1;
  } else if (exponent <= 1 - fracBits) {
    s1.sign = false;
    s1.exponent = 0;
    s1.fraction = 0;
  }
  Stage s = s1;
  for (int bit : {3, 2, 1})
    if (s.exponent >> bit & 1)
      s.fraction = s.expSign ? s.fraction >> (1 << bit) : s.fraction << (1 << bit);
  const uint32_t select = static_cast<uint32_t>(s.fraction >> (63 - fracBits - 31));
  uint32_t out = s.sign ? ~select + 1 : select;
  if (s.exponent & 1) {
    const uint32_t shifted = s.expSign ? select >> 1 : select << 1;
    out = s.sign ? ~shifted + 1 : shifted;
  }
  return out;
}

int64_t toRaw32(uint32_t word) { return static_cast<int32_t>(word); }

const FixedFormat q16_16{32, 16};

}  // namespace

TEST_CASE("RTL conversion equals the printed pipeline outside saturation", "[fixed]") {
  std::mt19937 random(7);
  std::uniform_int_distribution<uint32_t> mantissa(0, 0x7FFFFF);
  for (int exponent = -130; exponent <= 14; ++exponent) {
    for (int i = 0; i < 200; ++i) {
      for (uint32_t sign : {0u, 1u}) {
        const uint32_t biased = static_cast<uint32_t>(std::clamp(exponent + 127, 0, 254));
        const uint32_t bits = sign << 31 | biased << 23 | mantissa(random);
        INFO("float bits " << std::hex << bits);
        REQUIRE(floatToFixed(bits, q16_16, FloatConversion::Rtl) ==
                toRaw32(printedRtlFloatToFixed(bits)));
      }
    }
  }
}

TEST_CASE("Saturation repairs the printed branch, which yields 0", "[fixed]") {
  for (float value : {32768.0f, 1e9f, INFINITY}) {
    REQUIRE(printedRtlFloatToFixed(floatBits(value)) == 0);
    REQUIRE(printedRtlFloatToFixed(floatBits(-value)) == 0);
    for (FloatConversion conversion : {FloatConversion::Rtl, FloatConversion::Exact}) {
      REQUIRE(floatToFixed(floatBits(value), q16_16, conversion) == 0x7FFFFFFF);
      REQUIRE(floatToFixed(floatBits(-value), q16_16, conversion) == -0x80000000LL);
    }
  }
}

TEST_CASE("RTL conversion drops the last bit for odd positive exponents", "[fixed]") {
  // 2 + 2^-16: exponent 1 (odd), so the final left shift happens after the window is taken.
  const uint32_t bits = floatBits(2.0f + std::ldexp(1.0f, -16));
  REQUIRE(floatToFixed(bits, q16_16, FloatConversion::Exact) == 0x20001);
  REQUIRE(floatToFixed(bits, q16_16, FloatConversion::Rtl) == 0x20000);
  // Even exponent (4 + 2^-16 needs 19 significant bits, fits 24): both exact.
  const uint32_t even = floatBits(4.0f + std::ldexp(1.0f, -16));
  REQUIRE(floatToFixed(even, q16_16, FloatConversion::Rtl) == 0x40001);
  // Negative numbers truncate toward zero: -(2 + 2^-16) -> -0x20000 in the RTL.
  REQUIRE(floatToFixed(bits | 0x80000000u, q16_16, FloatConversion::Rtl) == -0x20000);
}

TEST_CASE("RTL conversion flushes magnitudes below 2^-14 to zero", "[fixed]") {
  REQUIRE(floatToFixed(floatBits(std::ldexp(1.0f, -15)), q16_16, FloatConversion::Rtl) == 0);
  REQUIRE(floatToFixed(floatBits(std::ldexp(1.0f, -15)), q16_16, FloatConversion::Exact) == 2);
  REQUIRE(floatToFixed(floatBits(std::ldexp(1.0f, -14)), q16_16, FloatConversion::Rtl) == 4);
}

TEST_CASE("Exact conversion truncates toward zero", "[fixed]") {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> value(-32767.0, 32767.0);
  for (int i = 0; i < 20000; ++i) {
    const float x = static_cast<float>(value(random) / std::pow(2.0, i % 20));
    const double expected = std::trunc(static_cast<double>(x) * 65536.0);
    REQUIRE(floatToFixed(floatBits(x), q16_16, FloatConversion::Exact) ==
            static_cast<int64_t>(expected));
  }
}

TEST_CASE("Other formats convert and wrap at their own width", "[fixed]") {
  const FixedFormat q8_24{32, 24};
  REQUIRE(floatToFixed(floatBits(1.5f), q8_24, FloatConversion::Exact) == 0x1800000);
  REQUIRE(floatToFixed(floatBits(200.0f), q8_24, FloatConversion::Exact) == q8_24.maxRaw());
  const FixedFormat wide{48, 24};
  REQUIRE(floatToFixed(floatBits(-3.25f), wide, FloatConversion::Rtl) == -(13LL << 22));
  REQUIRE(floatToFixed(floatBits(1e6f), wide, FloatConversion::Exact) == (1000000LL << 24));
  REQUIRE(q16_16.wrap(0x7FFFFFFFLL + 1) == -0x80000000LL);
  REQUIRE(FixedFormat{12, 4}.wrap(2048) == -2048);
  REQUIRE_THROWS_WITH(FixedFormat({64, 16}).validate(), Catch::Contains("8 to 48"));
  REQUIRE_THROWS_WITH(FixedFormat({32, 31}).validate(), Catch::Contains("fraction bits"));
}
