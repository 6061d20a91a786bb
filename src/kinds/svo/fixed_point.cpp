#include "kinds/svo/fixed_point.h"

#include <cmath>
#include <stdexcept>

namespace rtu {

void FixedFormat::validate() const {
  if (totalBits < 8 || totalBits > 48)
    throw std::invalid_argument("fixed-point width must be 8 to 48 bits, got " +
                                std::to_string(totalBits));
  if (fractionBits < 1 || fractionBits > totalBits - 2)
    throw std::invalid_argument(
        "fixed-point fraction bits must be 1 to " + std::to_string(totalBits - 2) + " for a " +
        std::to_string(totalBits) + "-bit number, got " + std::to_string(fractionBits));
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

}  // namespace rtu
