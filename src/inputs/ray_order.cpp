#include "inputs/ray_order.h"

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <utility>

#include "inputs/ray_sampler.h"

namespace rtu {

namespace {

// Bits 9:0 of v spread to every third bit.
uint64_t spreadBits(uint64_t v) {
  uint64_t spread = 0;
  for (int b = 0; b < 10; ++b) spread |= (v >> b & 1) << (3 * b);
  return spread;
}

uint64_t octant(const RayRecord& ray) {
  return uint64_t{ray.direction[0] < 0.0f} | uint64_t{ray.direction[1] < 0.0f} << 1 |
         uint64_t{ray.direction[2] < 0.0f} << 2;
}

void sortByKey(std::vector<RayRecord>& rays) {
  std::array<float, 3> low, high;
  low.fill(std::numeric_limits<float>::max());
  high.fill(std::numeric_limits<float>::lowest());
  for (const RayRecord& ray : rays)
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], ray.origin[k]);
      high[k] = std::max(high[k], ray.origin[k]);
    }
  std::vector<std::pair<uint64_t, RayRecord>> keyed;
  keyed.reserve(rays.size());
  for (const RayRecord& ray : rays) {
    uint64_t morton = 0;
    for (int k = 0; k < 3; ++k) {
      const double extent = static_cast<double>(high[k]) - low[k];
      const double unit = extent > 0.0 ? (ray.origin[k] - static_cast<double>(low[k])) / extent
                                       : 0.0;
      morton |= spreadBits(std::min<uint64_t>(1023, static_cast<uint64_t>(unit * 1024.0))) << k;
    }
    keyed.emplace_back(octant(ray) << 30 | morton, ray);
  }
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (size_t i = 0; i < rays.size(); ++i) rays[i] = keyed[i].second;
}

}  // namespace

RayOrder parseRayOrder(const std::string& text) {
  if (text == "pixel") return RayOrder::Pixel;
  if (text == "shuffled") return RayOrder::Shuffled;
  if (text == "sorted") return RayOrder::Sorted;
  throw std::invalid_argument("--order " + text + ": choose pixel, shuffled or sorted");
}

const char* toString(RayOrder order) {
  switch (order) {
    case RayOrder::Shuffled: return "shuffled";
    case RayOrder::Sorted: return "sorted";
    default: return "pixel";
  }
}

void orderRays(std::vector<RayRecord>& rays, RayOrder order, uint64_t seed) {
  if (order == RayOrder::Sorted) sortByKey(rays);
  if (order != RayOrder::Shuffled) return;
  RaySampler sampler(seed, std::numeric_limits<uint64_t>::max());
  for (size_t i = rays.size(); i > 1; --i) std::swap(rays[i - 1], rays[sampler.next() % i]);
}

}  // namespace rtu
