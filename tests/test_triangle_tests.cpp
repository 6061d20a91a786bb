// The ray/triangle tests of geometry/triangle_tests.h: hand cases whose arithmetic is exact
// (powers of two), the shared result convention, and the watertight property on a grid of
// triangle pairs, where every ray aimed at a vertex or an edge midpoint inside the grid must hit.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "geometry/triangle_tests.h"

namespace rtu {
namespace {

template <class T>
struct Triangle {
  Vec3<T> v0, v1, v2;
};

template <class T>
Triangle<T> unitTriangle() {
  return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
}

// Each test on one ray and triangle, as a list so that every case runs all three.
std::vector<std::optional<TriangleHit<double>>> allTests(const Vec3<double>& o,
                                                         const Vec3<double>& d,
                                                         const Triangle<double>& tri,
                                                         double tMin = 0, double tMax = 1e30) {
  const auto f = [](const Vec3<double>& v) { return Vec3<float>(v); };
  const auto widen = [](const std::optional<TriangleHit<float>>& h) {
    return h ? std::optional<TriangleHit<double>>(TriangleHit<double>{h->t, h->u, h->v})
             : std::nullopt;
  };
  const float fMin = static_cast<float>(tMin), fMax = static_cast<float>(tMax);
  return {watertight<double>(o, d, tri.v0, tri.v1, tri.v2, tMin, tMax),
          widen(watertight<float>(f(o), f(d), f(tri.v0), f(tri.v1), f(tri.v2), fMin, fMax)),
          widen(mollerTrumbore(f(o), f(d), f(tri.v0), f(tri.v1), f(tri.v2), fMin, fMax))};
}

}  // namespace

TEST_CASE("Triangle tests: hand cases, exact in every precision", "[triangle_tests]") {
  const Triangle<double> tri = unitTriangle<double>();
  SECTION("a hit inside: t, and u, v weighing v1 and v2") {
    for (const auto& hit : allTests({0.25, 0.125, 2}, {0, 0, -0.5}, tri)) {
      REQUIRE(hit);
      CHECK(hit->t == 4.0);  // the direction is not normalised: 2 / 0.5
      CHECK(hit->u == 0.25);
      CHECK(hit->v == 0.125);
    }
  }
  SECTION("from below and slanted") {
    // From (0.5, 0, -1) along (-0.25, 0.5, 1): z = 0 at t = 1, at (0.25, 0.5, 0).
    for (const auto& hit : allTests({0.5, 0, -1}, {-0.25, 0.5, 1}, tri)) {
      REQUIRE(hit);
      CHECK(hit->t == 1.0);
      CHECK(hit->u == 0.25);
      CHECK(hit->v == 0.5);
    }
  }
  SECTION("misses: outside, behind, beyond tMax, parallel, edge-on") {
    for (const auto& hit : allTests({0.75, 0.75, 1}, {0, 0, -1}, tri)) CHECK_FALSE(hit);
    for (const auto& hit : allTests({0.25, 0.25, -1}, {0, 0, -1}, tri)) CHECK_FALSE(hit);
    for (const auto& hit : allTests({0.25, 0.25, 1}, {0, 0, -1}, tri, 0, 0.5)) CHECK_FALSE(hit);
    for (const auto& hit : allTests({0.25, 0.25, 1}, {1, 0, 0}, tri)) CHECK_FALSE(hit);
    for (const auto& hit : allTests({-1, 0.25, 0}, {1, 0, 0}, tri)) CHECK_FALSE(hit);
  }
  SECTION("tMin and tMax are inclusive") {
    for (const auto& hit : allTests({0.25, 0.25, 1}, {0, 0, -1}, tri, 1, 1)) {
      REQUIRE(hit);
      CHECK(hit->t == 1.0);
    }
  }
}

TEST_CASE("Triangle tests: the hit point from t and from u, v agree", "[triangle_tests]") {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  const Triangle<double> tri{{0.1, -0.3, 0.2}, {0.9, 0.2, -0.1}, {-0.2, 0.8, 0.4}};
  int hits = 0;
  for (int i = 0; i < 1000; ++i) {
    const Vec3<double> o{uniform(random), uniform(random), 2 + uniform(random)};
    const Vec3<double> target{uniform(random), uniform(random), uniform(random) * 0.3};
    const Vec3<double> d{target[0] - o[0], target[1] - o[1], target[2] - o[2]};
    const auto hit = watertight<double>(o, d, tri.v0, tri.v1, tri.v2, 0, 1e30);
    if (!hit) continue;
    ++hits;
    for (int k = 0; k < 3; ++k) {
      const double alongRay = o[k] + hit->t * d[k];
      const double fromWeights =
          (1 - hit->u - hit->v) * tri.v0[k] + hit->u * tri.v1[k] + hit->v * tri.v2[k];
      CHECK(std::abs(alongRay - fromWeights) < 1e-12);
    }
  }
  CHECK(hits > 100);
}

TEST_CASE("Triangle tests: a float edge function that rounds to 0 is decided in double",
          "[triangle_tests]") {
  // A ray along +z through the xy plane's origin; the triangles (R, B, C) and (L, C, B) share
  // the edge from B to C, which passes just beside the origin: its edge function,
  // (1 + 2^-12)(-1 - 2^-12) - (1 + 2^-11)(-1) = -2^-24 exactly, rounds to 0 in float (the first
  // product is a tie, rounded to even). Decided in double, the ray hits (L, C, B) alone; taken as
  // 0, it would hit both.
  const float e12 = std::ldexp(1.0f, -12), e11 = std::ldexp(1.0f, -11);
  const Vec3<float> o{0, 0, -1}, d{0, 0, 1};
  const Vec3<float> b{-1, -1 - e12, 0}, c{1 + e12, 1 + e11, 0};
  const Vec3<float> right{2, -2, 0}, left{-2, 2, 0};
  CHECK_FALSE(watertight<float>(o, d, right, b, c, 0, 10));
  CHECK(watertight<float>(o, d, left, c, b, 0, 10));
  const auto wide = [](const Vec3<float>& v) { return Vec3<double>(v); };
  CHECK_FALSE(watertight<double>(wide(o), wide(d), wide(right), wide(b), wide(c), 0, 10));
  CHECK(watertight<double>(wide(o), wide(d), wide(left), wide(c), wide(b), 0, 10));
}

TEMPLATE_TEST_CASE("Triangle tests: watertight on a grid's shared edges and vertices",
                   "[triangle_tests]", float, double) {
  // An 8 x 8 grid of unit squares in the plane z = 0.3 x + 0.2 y (so nothing is axis-aligned),
  // each split along its diagonal into two triangles. Rays from scattered origins above it, aimed
  // at every interior vertex and edge midpoint, must hit some triangle: no ray falls through a
  // crack between two triangles.
  using T = TestType;
  constexpr int n = 8;
  const auto point = [](double x, double y) {
    return Vec3<T>{static_cast<T>(x), static_cast<T>(y), static_cast<T>(0.3 * x + 0.2 * y)};
  };
  std::vector<Triangle<T>> triangles;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      triangles.push_back({point(i, j), point(i + 1, j), point(i + 1, j + 1)});
      triangles.push_back({point(i, j), point(i + 1, j + 1), point(i, j + 1)});
    }
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(-3, 11);
  int rays = 0, falseMisses = 0, mollerMisses = 0;
  for (int twiceX = 1; twiceX < 2 * n; ++twiceX)
    for (int twiceY = 1; twiceY < 2 * n; ++twiceY) {
      if (twiceX % 2 == 1 && twiceY % 2 == 1) continue;  // a square's centre: not on an edge
      const Vec3<T> target = point(twiceX / 2.0, twiceY / 2.0);
      const Vec3<T> o{static_cast<T>(uniform(random)), static_cast<T>(uniform(random)), 7};
      const Vec3<T> d{target[0] - o[0], target[1] - o[1], target[2] - o[2]};
      bool hit = false, mollerHit = false;
      for (const Triangle<T>& tri : triangles) {
        hit = hit || watertight<T>(o, d, tri.v0, tri.v1, tri.v2, 0, 1e30f);
        if constexpr (std::is_same_v<T, float>)
          mollerHit = mollerHit || mollerTrumbore(o, d, tri.v0, tri.v1, tri.v2, 0, 1e30f);
      }
      ++rays;
      falseMisses += !hit;
      mollerMisses += !mollerHit;
    }
  INFO(rays << " rays; Moller-Trumbore float32 missed "
            << (std::is_same_v<T, float> ? std::to_string(mollerMisses) : "(not run)"));
  CHECK(rays == 15 * 15 - 8 * 8);  // half-integer points that lie on an edge or a vertex
  CHECK(falseMisses == 0);
}

}  // namespace rtu
