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
// Inline: the job manager converts six values per ray.
inline int64_t floatToFixed(uint32_t floatBits, const FixedFormat& format,
                            FloatConversion conversion) {
  // m * 2^shift rounded toward zero, for a positive 24-bit significand m.
  const auto scaleSignificand = [](int64_t significand, int shift) -> int64_t {
    if (shift >= 0) return significand << shift;
    return -shift >= 63 ? 0 : significand >> -shift;
  };
  const bool negative = (floatBits >> 31) != 0;
  const int exponent = static_cast<int>((floatBits >> 23) & 0xFF) - 127;
  const int64_t significand = (floatBits & 0x7FFFFF) | 0x800000;
  const int fraction = format.fractionBits;

  // The RTL saturates once the exponent cannot fit (C.2.1 first stage); its printed saturation
  // values select zero bits, which is repaired here to the largest and smallest numbers.
  if (exponent >= format.totalBits - 1 - fraction)
    return negative ? format.minRaw() : format.maxRaw();

  int64_t magnitude;
  if (conversion == FloatConversion::Rtl) {
    if (exponent <= 1 - fraction) return 0;
    const int shift = exponent - 23 + fraction;
    const bool lateLeftShift = exponent > 0 && (exponent & 1);
    magnitude = lateLeftShift ? scaleSignificand(significand, shift - 1) << 1
                              : scaleSignificand(significand, shift);
  } else {
    if (exponent == -127) return 0;  // zero and subnormals are below every supported resolution
    magnitude = scaleSignificand(significand, exponent - 23 + fraction);
  }
  return format.wrap(negative ? -magnitude : magnitude);
}

}  // namespace rtu
