#pragma once
// Two's complement fixed-point numbers as the RTL computes them: a raw integer of `totalBits`
// bits, `fractionBits` of which are fraction. Additions wrap, right shifts truncate toward
// minus infinity (SystemVerilog `>>>`). The thesis configuration is 32 bits with 16 fraction bits.

#include <cstdint>
#include <string>

namespace rtu {

struct FixedFormat {
  int totalBits = 32;
  int fractionBits = 16;

  // Throws std::invalid_argument unless 8 <= totalBits <= 48 and 1 <= fractionBits < totalBits - 1.
  void validate() const;

  // Reduces `raw` to totalBits and sign-extends it, as a register of that width would hold it.
  int64_t wrap(int64_t raw) const {
    const int unused = 64 - totalBits;
    return static_cast<int64_t>(static_cast<uint64_t>(raw) << unused) >> unused;
  }
  int64_t maxRaw() const { return (int64_t{1} << (totalBits - 1)) - 1; }
  int64_t minRaw() const { return -(int64_t{1} << (totalBits - 1)); }
  int64_t one() const { return int64_t{1} << fractionBits; }
  double toDouble(int64_t raw) const;

  std::string describe() const;  // "Q16.16 (32 bits)"
};

// How float32 values become fixed point.
enum class FloatConversion {
  // Thesis appendix C.2.1 as the hardware computes it: values with |x| < 2^-14 become 0 and,
  // for odd positive exponents, the final 1-bit left shift happens after the output window is
  // selected, so the least significant bit is always 0. Saturation is repaired (see docs).
  Rtl,
  // Truncation toward zero of x * 2^fractionBits, saturated to the representable range.
  Exact,
};

const char* toString(FloatConversion conversion);
FloatConversion parseFloatConversion(const std::string& name);  // "rtl" or "exact"

// Converts the IEEE-754 single-precision value with bit pattern `floatBits`.
// NaN and infinities saturate according to their sign bit, as the RTL does.
int64_t floatToFixed(uint32_t floatBits, const FixedFormat& format, FloatConversion conversion);

}  // namespace rtu
