#include "fixed_point.h"

#include <cmath>
#include <stdexcept>

namespace rtu {

void FixedFormat::validate() const {
  if (totalBits < 8 || totalBits > 48)
    throw std::invalid_argument("fixed-point width must be 8 to 48 bits, got " +
                                std::to_string(totalBits));
  if (fractionBits < 1 || fractionBits > totalBits - 2)
    throw std::invalid_argument("fixed-point fraction bits must be 1 to " +
                                std::to_string(totalBits - 2) + " for a " +
                                std::to_string(totalBits) + "-bit number, got " +
                                std::to_string(fractionBits));
}

double FixedFormat::toDouble(int64_t raw) const {
  return std::ldexp(static_cast<double>(raw), -fractionBits);
}

std::string FixedFormat::describe() const {
  return "Q" + std::to_string(totalBits - fractionBits) + "." + std::to_string(fractionBits) +
         " (" + std::to_string(totalBits) + " bits)";
}

const char* toString(FloatConversion conversion) {
  return conversion == FloatConversion::Rtl ? "rtl" : "exact";
}

FloatConversion parseFloatConversion(const std::string& name) {
  if (name == "rtl") return FloatConversion::Rtl;
  if (name == "exact") return FloatConversion::Exact;
  throw std::invalid_argument("unknown float conversion '" + name + "' (expected rtl or exact)");
}

namespace {

// m * 2^shift rounded toward zero, for a positive 24-bit significand m.
int64_t scaleSignificand(int64_t significand, int shift) {
  if (shift >= 0) return significand << shift;
  return -shift >= 63 ? 0 : significand >> -shift;
}

}  // namespace

int64_t floatToFixed(uint32_t floatBits, const FixedFormat& format, FloatConversion conversion) {
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
