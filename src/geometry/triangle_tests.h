#pragma once
// Ray/triangle tests in the precisions the triangle kinds and their oracle use, with one result
// convention: a hit at distance t along the ray's direction (not normalised) with barycentrics
// (u, v) such that the point is (1 - u - v) v0 + u v1 + v v2, within [tMin, tMax].
//
// watertight<T>   Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection" (JCGT 2013):
//                 shear the triangle into the ray's space (kz the axis of the largest |d|, the
//                 lowest on ties; kx, ky the next two cyclically, swapped when d[kz] < 0 so the
//                 winding keeps its sign), then edge functions U, V, W. For float, any edge
//                 function exactly 0 is recomputed in double, as pbrt-v4 does: a ray through an
//                 edge or vertex is then decided consistently for the triangles that share it,
//                 so a closed mesh has no hole. det = U + V + W = 0 (a triangle seen edge-on) is
//                 a miss. Every operation is its own statement: the project builds in ISO C++
//                 mode, where GCC contracts nothing into fused multiply-adds.
// mollerTrumbore  Moller and Trumbore 1997 in float32: e1 = v1 - v0, e2 = v2 - v0, p = d x e2,
//                 det = e1 . p with dots as (x x' + y y') + z z'; det == 0 is a miss, with no
//                 absolute epsilon (it would depend on the scene's scale). Not watertight: a ray
//                 through a shared edge may miss both triangles.

#include <cmath>
#include <optional>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace rtu {

// GLM's vectors: each product and sum rounded on its own, dot products as (x x' + y y') + z z'.
template <class T>
using Vec3 = glm::vec<3, T>;

template <class T>
struct TriangleHit {
  T t = 0, u = 0, v = 0;
};

namespace triangle_detail {

// a_x b_y - a_y b_x, the sheared 2D edge function, in T.
template <class T>
T edge(T ax, T ay, T bx, T by) {
  const T first = ax * by;
  const T second = ay * bx;
  return first - second;
}

}  // namespace triangle_detail

// What the watertight test precomputes per ray.
template <class T>
struct ShearedRay {
  Vec3<T> origin;
  int kx = 0, ky = 1, kz = 2;
  T sx = 0, sy = 0, sz = 1;

  ShearedRay(const Vec3<T>& o, const Vec3<T>& d) : origin(o) {
    kz = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(d[k]) > std::abs(d[kz])) kz = k;
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);
    sx = d[kx] / d[kz];
    sy = d[ky] / d[kz];
    sz = T(1) / d[kz];
  }
};

template <class T>
std::optional<TriangleHit<T>> watertight(const ShearedRay<T>& ray, const Vec3<T>& v0,
                                         const Vec3<T>& v1, const Vec3<T>& v2, T tMin, T tMax) {
  using triangle_detail::edge;
  const Vec3<T> a = v0 - ray.origin, b = v1 - ray.origin, c = v2 - ray.origin;
  const auto sheared = [&ray](const Vec3<T>& p, T s, int k) {
    const T shift = s * p[ray.kz];
    return p[k] - shift;
  };
  const T ax = sheared(a, ray.sx, ray.kx), ay = sheared(a, ray.sy, ray.ky);
  const T bx = sheared(b, ray.sx, ray.kx), by = sheared(b, ray.sy, ray.ky);
  const T cx = sheared(c, ray.sx, ray.kx), cy = sheared(c, ray.sy, ray.ky);
  // U weighs v0, V v1, W v2.
  T u = edge(cx, cy, bx, by), v = edge(ax, ay, cx, cy), w = edge(bx, by, ax, ay);
  if constexpr (sizeof(T) < sizeof(double)) {
    if (u == 0 || v == 0 || w == 0) {
      u = static_cast<T>(edge<double>(cx, cy, bx, by));
      v = static_cast<T>(edge<double>(ax, ay, cx, cy));
      w = static_cast<T>(edge<double>(bx, by, ax, ay));
    }
  }
  if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return std::nullopt;
  T det = u + v;
  det = det + w;
  if (det == 0) return std::nullopt;
  const int kz = ray.kz;
  const T az = ray.sz * a[kz], bz = ray.sz * b[kz], cz = ray.sz * c[kz];
  T scaled = u * az;
  const T second = v * bz;
  scaled = scaled + second;
  const T third = w * cz;
  scaled = scaled + third;
  // t = scaled / det within [tMin, tMax], tested before the division with det's sign folded in.
  const T sign = det < 0 ? T(-1) : T(1);
  const T signedScaled = scaled * sign, absDet = det * sign;
  if (signedScaled < tMin * absDet || signedScaled > tMax * absDet) return std::nullopt;
  const T inverse = T(1) / det;
  return TriangleHit<T>{scaled * inverse, v * inverse, w * inverse};
}

template <class T>
std::optional<TriangleHit<T>> watertight(const Vec3<T>& origin, const Vec3<T>& direction,
                                         const Vec3<T>& v0, const Vec3<T>& v1, const Vec3<T>& v2,
                                         T tMin, T tMax) {
  return watertight(ShearedRay<T>(origin, direction), v0, v1, v2, tMin, tMax);
}

inline std::optional<TriangleHit<float>> mollerTrumbore(
    const Vec3<float>& origin, const Vec3<float>& direction, const Vec3<float>& v0,
    const Vec3<float>& v1, const Vec3<float>& v2, float tMin, float tMax) {
  const Vec3<float> e1 = v1 - v0, e2 = v2 - v0;
  const Vec3<float> p = glm::cross(direction, e2);
  const float det = glm::dot(e1, p);
  if (det == 0.0f) return std::nullopt;
  const float inverse = 1.0f / det;
  const Vec3<float> s = origin - v0;
  const float u = glm::dot(s, p) * inverse;
  if (u < 0.0f || u > 1.0f) return std::nullopt;
  const Vec3<float> q = glm::cross(s, e1);
  const float v = glm::dot(direction, q) * inverse;
  if (v < 0.0f) return std::nullopt;
  const float sum = u + v;
  if (sum > 1.0f) return std::nullopt;
  const float t = glm::dot(e2, q) * inverse;
  if (t < tMin || t > tMax) return std::nullopt;
  return TriangleHit<float>{t, u, v};
}

}  // namespace rtu
