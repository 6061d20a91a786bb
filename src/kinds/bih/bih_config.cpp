#include "kinds/bih/bih_config.h"

#include <stdexcept>
#include <string>

namespace rtu {
namespace {

void checkCycles(const char* key, uint32_t value) {
  if (value < 1 || value > kMaxBihUnitCycles)
    throw std::invalid_argument(std::string(key) + " must be 1 to " +
                                std::to_string(kMaxBihUnitCycles) + " cycles, got " +
                                std::to_string(value));
}

bool sameFormat(const FixedTriangleFormat& a, const FixedTriangleFormat& b) {
  return a.n == b.n && a.m == b.m && a.E == b.E && a.T == b.T && a.C == b.C &&
         a.listing == b.listing;
}

}  // namespace

std::string bihFormatName(const FixedTriangleFormat& format) {
  if (sameFormat(format, kC99Format)) return "c99";
  if (sameFormat(format, kVhdlFormat)) return "vhdl";
  const auto f = [](const char* name, int value) { return name + std::to_string(value); };
  return std::string(format.listing == FixedListing::Vhdl ? "vhdl" : "c99") + "(" +
         f("n=", format.n) + f(" m=", format.m) + f(" E=", format.E) + f(" T=", format.T) +
         f(" C=", format.C) + ")";
}

FixedTriangleFormat parseBihFormat(const std::string& name) {
  if (name == "c99") return kC99Format;
  if (name == "vhdl") return kVhdlFormat;
  throw std::invalid_argument("unknown BIH format '" + name + "': give c99 or vhdl");
}

void BihConfig::validate() const {
  checkCycles("bih.triangle.latency", cycles.triangleLatency);
  checkCycles("bih.triangle.interval", cycles.triangleInterval);
  if (cycles.triangleInterval > cycles.triangleLatency)
    throw std::invalid_argument(
        "bih.triangle.interval (" + std::to_string(cycles.triangleInterval) +
        ") exceeds bih.triangle.latency (" + std::to_string(cycles.triangleLatency) +
        "): a unit takes its next test no later than it answers one");
  try {
    validateFixedTriangleFormat(format);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("accel.bih_format: ") + e.what());
  }
}

}  // namespace rtu
