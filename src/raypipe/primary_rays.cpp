#include "raypipe/primary_rays.h"

#include <stdexcept>
#include <string>

#include "kinds/kd/binary32.h"

namespace rtu {
namespace {

// The counter's even bits (x_index = {8, 6, 4, 2, 0} in the RTL) or odd bits (y_index).
int interleavedBits(uint32_t code, int first) {
  int value = 0;
  for (int bit = 0; 2 * bit + first < 32; ++bit) value |= ((code >> (2 * bit + first)) & 1) << bit;
  return value;
}

void appendBlock(int left, int top, int width, int height, PrgFrameSize size,
                 std::vector<PrgPixel>& order) {
  for (int y = top; y < top + height; ++y)
    for (int x = left; x < left + width; ++x)
      order.push_back(PrgPixel{static_cast<uint32_t>(y) * static_cast<uint32_t>(size.width) +
                                   static_cast<uint32_t>(x),
                               x, y});
}

}  // namespace

PrgFrameSize prgLevelSize(int level) {
  if (level < 0 || level >= kPrgLevels)
    throw std::invalid_argument("raypipe.level = " + std::to_string(level) +
                                ": the seed's levels are 0 (20x15) to 5 (640x480)");
  return PrgFrameSize{kPrgBlockWidth << level, kPrgBlockHeight << level};
}

std::vector<PrgPixel> prgIssueOrder(PrgFrameSize size) {
  if (size.width < 1 || size.height < 1)
    throw std::invalid_argument("the primary ray generator needs a frame of at least 1x1, got " +
                                std::to_string(size.width) + "x" + std::to_string(size.height));
  const size_t pixels = static_cast<size_t>(size.width) * static_cast<size_t>(size.height);
  std::vector<PrgPixel> order;
  order.reserve(pixels);
  if (size.width % kPrgBlockWidth != 0 || size.height % kPrgBlockHeight != 0) {
    appendBlock(0, 0, size.width, size.height, size, order);
    return order;
  }
  const int columns = size.width / kPrgBlockWidth, rows = size.height / kPrgBlockHeight;
  // Codes run until every block is issued; those outside a non-square grid are skipped.
  for (uint32_t code = 0; order.size() < pixels; ++code) {
    const int column = interleavedBits(code, 0), row = interleavedBits(code, 1);
    if (column < columns && row < rows)
      appendBlock(column * kPrgBlockWidth, row * kPrgBlockHeight, kPrgBlockWidth, kPrgBlockHeight,
                  size, order);
  }
  return order;
}

KdRay prgRay(const RaypipeCamera& camera, PrgFrameSize size, int x, int y) {
  // pw and the half width: the RTL's constants at its levels (480 / rows exactly), else rounded.
  const float pw = static_cast<float>(480.0 / size.height);
  const float halfWidth = static_cast<float>(size.width * (480.0 / size.height) / 2);
  const float screenDistance = 240.0f;  // SCREEN_DIST, 0x43700000
  const int yPrg = size.height - 1 - y;
  // altfp_convert of a small integer is exact.
  const float u = add32(mul32(static_cast<float>(x), pw), -halfWidth);
  const float v = add32(mul32(static_cast<float>(yPrg), pw), -240.0f);
  KdRay ray;
  ray.origin = camera.eye;
  for (int c = 0; c < 3; ++c)
    ray.direction[c] = add32(add32(mul32(u, camera.u[c]), mul32(v, camera.v[c])),
                             mul32(camera.w[c], screenDistance));
  return ray;
}

std::vector<PrimaryRay> primaryRays(const RaypipeCamera& camera, PrgFrameSize size) {
  std::vector<PrimaryRay> rays;
  const std::vector<PrgPixel> order = prgIssueOrder(size);
  rays.reserve(order.size());
  for (const PrgPixel& pixel : order)
    rays.push_back(PrimaryRay{pixel, prgRay(camera, size, pixel.x, pixel.y)});
  return rays;
}

}  // namespace rtu
