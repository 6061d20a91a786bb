#pragma once
// The colours of seed 001's simple shader (R1 RAYTRACER/shader/simple_shade_unit.sv calc_color,
// COMMON/defines.sv; specs/001 §2.2 "Shader"), the final build's: a pixel in RGB565
// {r 5, g 6, b 5} from its primary ray's outcome. The shadow colours are not here: the simple
// shader never issues a shadow ray.

#include <array>
#include <cstdint>

namespace rtu {

constexpr uint16_t kShadeBoxMiss = 0b11111'000000'11111;  // magenta, "for testing"
constexpr uint16_t kShadeMiss = 0xFFFF;                   // MISS_COLOR, white
// TRI_0_COLOR .. TRI_3_COLOR, by the hit triangle's id modulo 4: grey, yellow, green, red.
constexpr std::array<uint16_t, 4> kShadeTriangle = {0b10101'101010'10101, 0b11111'111111'00000,
                                                    0b00000'110000'00000, 0b11111'000000'00000};

// calc_color: a box miss first, then a miss, then the hit's triangle id.
inline uint16_t simpleShade(bool boxMiss, bool hit, uint32_t triangle) {
  if (boxMiss) return kShadeBoxMiss;
  if (!hit) return kShadeMiss;
  return kShadeTriangle[triangle % 4];
}

// RGB565 to 8 bits a channel, each channel's high bits repeated into its low ones (so 0 stays 0
// and full scale becomes 255), as a display expands it.
std::array<uint8_t, 3> rgb888(uint16_t rgb565);

}  // namespace rtu
