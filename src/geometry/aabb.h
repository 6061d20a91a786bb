#pragma once
// Axis-aligned bounding boxes for building acceleration structures: in double while a builder
// works (surface areas for the SAH), then rounded outward to float32 for a memory image, so that
// the stored box still encloses everything the double box did.

#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <glm/vector_relational.hpp>

namespace rtu {

template <class T>
struct Aabb {
  using Point = glm::vec<3, T>;
  // Empty: the identity of grow() and merge(); its area is 0.
  Point lower{std::numeric_limits<T>::infinity()};
  Point upper{-std::numeric_limits<T>::infinity()};

  bool empty() const { return lower.x > upper.x || lower.y > upper.y || lower.z > upper.z; }
  void grow(const Point& point) {
    lower = glm::min(lower, point);
    upper = glm::max(upper, point);
  }
  // An empty box's infinite bounds leave the minimum and maximum unchanged: no test needed.
  void merge(const Aabb& box) {
    lower = glm::min(lower, box.lower);
    upper = glm::max(upper, box.upper);
  }
  Point extent() const { return upper - lower; }
  // 2 (xy + yz + zx); 0 for an empty box.
  T area() const {
    if (empty()) return 0;
    const Point e = extent();
    return 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
  Point centre() const { return (lower + upper) / T(2); }
  bool contains(const Aabb& box) const {
    return glm::all(glm::lessThanEqual(lower, box.lower)) &&
           glm::all(glm::lessThanEqual(box.upper, upper));
  }
};

// The float32 box that encloses `box`: each bound rounded to nearest, then one step outward when
// that rounding went inward. An empty box stays empty.
inline Aabb<float> roundOutward(const Aabb<double>& box) {
  Aabb<float> out;
  if (box.empty()) return out;
  constexpr float kInfinity = std::numeric_limits<float>::infinity();
  for (int k = 0; k < 3; ++k) {
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
