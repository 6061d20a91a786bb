#pragma once
// A float32's bit pattern as a memory word and back: host records, memory images and results
// store float32 values as 32-bit words.

#include <cstdint>
#include <cstring>

namespace rtu {

inline uint32_t floatBits(float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

inline float bitsToFloat(uint32_t bits) {
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace rtu
