#include "kinds/bih/grid.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>

#include "kinds/bih/fixed_arith.h"

namespace rtu {
namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

double longestSide(const Aabb<double>& box) {
  const glm::dvec3 e = box.extent();
  return std::max({e.x, e.y, e.z});
}

// The part [enter, exit] of t >= 0 where origin + t direction lies in the box (slabs in double).
std::optional<std::pair<double, double>> clip(const Aabb<double>& box, const Ray& ray) {
  double enter = 0, exit = INFINITY;
  for (int k = 0; k < 3; ++k) {
    const double o = ray.origin[k], d = ray.direction[k];
    if (d == 0) {
      if (o < box.lower[k] || o > box.upper[k]) return std::nullopt;
      continue;
    }
    double near = (box.lower[k] - o) / d, far = (box.upper[k] - o) / d;
    if (near > far) std::swap(near, far);
    enter = std::max(enter, near);
    exit = std::min(exit, far);
  }
  if (enter > exit) return std::nullopt;
  return std::make_pair(enter, exit);
}

}  // namespace

Aabb<double> gridBoxAround(const Aabb<double>& vertices, const FixedTriangleFormat& format) {
  validateFixedTriangleFormat(format);
  const double units = static_cast<double>(pow2(format.n) - 1);
  if (units <= 4 * kGridMargin) return vertices;  // a grid of a few units: no room to keep free
  const double margin = kGridMargin * longestSide(vertices) / (units - 2 * kGridMargin);
  Aabb<double> box = vertices;
  box.lower -= glm::dvec3(margin);
  box.upper += glm::dvec3(margin);
  return box;
}

SceneGrid::SceneGrid(const Aabb<double>& box, const FixedTriangleFormat& format)
    : format_(format), box_(box), scale_(0) {
  validateFixedTriangleFormat(format);
  if (box.empty() || !finite(box.lower) || !finite(box.upper) || !(longestSide(box) > 0))
    throw std::invalid_argument("scene grid: the scene box must be finite and not a point");
  scale_ = static_cast<double>(pow2(format.n) - 1) / longestSide(box);
}

GridPoint SceneGrid::quantise(const glm::dvec3& p) const {
  const double highest = static_cast<double>(pow2(format_.n) - 1);
  GridPoint grid;
  // nearbyint rounds half to even in the default rounding mode; the clamp only catches a point
  // that double arithmetic (or clipping) put an ulp outside the box.
  for (int k = 0; k < 3; ++k)
    grid[k] = static_cast<int64_t>(
        std::clamp(std::nearbyint((p[k] - box_.lower[k]) * scale_), 0.0, highest));
  return grid;
}

int64_t inverseDirection(int64_t omega, const FixedTriangleFormat& format) {
  const Int128 divisor = omega == 0 ? 1 : omega;
  if (format.listing == FixedListing::C99)
    return static_cast<int64_t>(pow2(format.m + format.C) / divisor);
  const Int128 highest = pow2(format.m + format.C - 1) - 1;
  return static_cast<int64_t>(clampTo(pow2(format.m - 1 + format.C) / divisor, -highest, highest));
}

std::optional<GridRay> SceneGrid::quantise(const Ray& ray) const {
  const double length = glm::length(ray.direction);
  if (!finite(ray.origin) || !finite(ray.direction) || !(length > 0))
    throw std::invalid_argument("scene grid: a ray needs a finite origin and a non-zero direction");
  const auto span = clip(box_, ray);
  if (!span) return std::nullopt;
  GridRay grid;
  grid.tClip = span->first;
  grid.worldPerGridUnit = 1.0 / (scale_ * length);
  grid.origin = quantise(ray.origin + span->first * ray.direction);
  const double unit = std::ldexp(1.0, format_.m - 1);
  for (int k = 0; k < 3; ++k) {
    const double code = std::nearbyint(ray.direction[k] / length * unit);
    grid.omega[k] = static_cast<int64_t>(std::clamp(code, -unit, unit - 1));
    grid.idir[k] = inverseDirection(grid.omega[k], format_);
  }
  return grid;
}

}  // namespace rtu
