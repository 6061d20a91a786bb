#pragma once
// Axis-aligned bounding boxes for building acceleration structures: in double while a builder
// works (surface areas for the SAH), then rounded outward to float32 for a memory image, so that
// the stored box still encloses everything the double box did.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace rtu {

template <class T>
struct Aabb {
  // Empty: the identity of grow() and merge(); its area is 0.
  std::array<T, 3> lower{std::numeric_limits<T>::infinity(), std::numeric_limits<T>::infinity(),
                         std::numeric_limits<T>::infinity()};
  std::array<T, 3> upper{-std::numeric_limits<T>::infinity(), -std::numeric_limits<T>::infinity(),
                         -std::numeric_limits<T>::infinity()};

  bool empty() const { return lower[0] > upper[0] || lower[1] > upper[1] || lower[2] > upper[2]; }
  void grow(const std::array<T, 3>& point) {
    for (size_t k = 0; k < 3; ++k) {
      lower[k] = std::min(lower[k], point[k]);
      upper[k] = std::max(upper[k], point[k]);
    }
  }
  void merge(const Aabb& box) {
    if (box.empty()) return;
    grow(box.lower);
    grow(box.upper);
  }
  std::array<T, 3> extent() const {
    return {upper[0] - lower[0], upper[1] - lower[1], upper[2] - lower[2]};
  }
  // 2 (xy + yz + zx); 0 for an empty box.
  T area() const {
    if (empty()) return 0;
    const std::array<T, 3> e = extent();
    return 2 * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
  }
  std::array<T, 3> centre() const {
    return {(lower[0] + upper[0]) / 2, (lower[1] + upper[1]) / 2, (lower[2] + upper[2]) / 2};
  }
  bool contains(const Aabb& box) const {
    for (size_t k = 0; k < 3; ++k)
      if (box.lower[k] < lower[k] || box.upper[k] > upper[k]) return false;
    return true;
  }
};

// The float32 box that encloses `box`: each bound rounded to nearest, then one step outward when
// that rounding went inward. An empty box stays empty.
inline Aabb<float> roundOutward(const Aabb<double>& box) {
  Aabb<float> out;
  if (box.empty()) return out;
  constexpr float kInfinity = std::numeric_limits<float>::infinity();
  for (size_t k = 0; k < 3; ++k) {
    float lower = static_cast<float>(box.lower[k]);
    if (static_cast<double>(lower) > box.lower[k]) lower = std::nextafter(lower, -kInfinity);
    float upper = static_cast<float>(box.upper[k]);
    if (static_cast<double>(upper) < box.upper[k]) upper = std::nextafter(upper, kInfinity);
    out.lower[k] = lower;
    out.upper[k] = upper;
  }
  return out;
}

}  // namespace rtu
