#include "raypipe/simple_shader.h"

namespace rtu {
namespace {

uint8_t expand(uint32_t value, int bits) {
  const uint32_t high = value << (8 - bits);
  return static_cast<uint8_t>(high | (high >> bits));
}

}  // namespace

std::array<uint8_t, 3> rgb888(uint16_t rgb565) {
  return {expand(rgb565 >> 11, 5), expand((rgb565 >> 5) & 0x3F, 6), expand(rgb565 & 0x1F, 5)};
}

}  // namespace rtu
