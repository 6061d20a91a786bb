// Bounding boxes (geometry/aabb.h): growing, surface area, and the outward rounding to float32
// that keeps a stored box around its double original.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "geometry/aabb.h"

namespace rtu {

TEST_CASE("Aabb: grows from empty, its area and centre", "[aabb]") {
  Aabb<double> box;
  CHECK(box.empty());
  CHECK(box.area() == 0);
  box.grow({1, 2, 3});
  CHECK_FALSE(box.empty());
  CHECK(box.area() == 0);  // a point
  box.grow({2, 4, 7});
  CHECK(box.extent() == glm::dvec3{1, 2, 4});
  CHECK(box.area() == 2 * (1 * 2 + 2 * 4 + 4 * 1));
  CHECK(box.centre() == glm::dvec3{1.5, 3, 5});
  Aabb<double> other;
  other.grow({-1, 2, 3});
  other.merge(Aabb<double>{});  // an empty box changes nothing
  box.merge(other);
  CHECK(box.lower == glm::dvec3{-1, 2, 3});
  CHECK(box.contains(other));
  CHECK_FALSE(other.contains(box));
}

TEST_CASE("Aabb: rounded outward to float32, it still encloses the double box", "[aabb]") {
  SECTION("bounds exact in float32 stay") {
    Aabb<double> box;
    box.grow({0.5, -2, 1024});
    box.grow({0.75, 3, 2048});
    const Aabb<float> out = roundOutward(box);
    CHECK(out.lower == glm::vec3{0.5f, -2, 1024});
    CHECK(out.upper == glm::vec3{0.75f, 3, 2048});
  }
  SECTION("0.1 rounds to nearest upward in float32, so as a lower bound it steps down") {
    Aabb<double> box;
    box.grow({0.1, 0.1, 0.1});
    const Aabb<float> out = roundOutward(box);
    CHECK(static_cast<float>(0.1) > 0.1);  // the premise
    CHECK(out.lower[0] == std::nextafter(static_cast<float>(0.1), 0.0f));
    CHECK(out.upper[0] == static_cast<float>(0.1));
  }
  SECTION("random boxes") {
    std::mt19937 random(3);
    std::uniform_real_distribution<double> uniform(-1e3, 1e3);
    for (int i = 0; i < 1000; ++i) {
      Aabb<double> box;
      box.grow({uniform(random), uniform(random), uniform(random)});
      box.grow({uniform(random), uniform(random), uniform(random)});
      const Aabb<float> out = roundOutward(box);
      for (int k = 0; k < 3; ++k) {
        CHECK(static_cast<double>(out.lower[k]) <= box.lower[k]);
        CHECK(static_cast<double>(out.upper[k]) >= box.upper[k]);
        // at most one float step beyond the nearest
        CHECK(std::nextafter(out.lower[k], INFINITY) >= static_cast<float>(box.lower[k]));
        CHECK(std::nextafter(out.upper[k], -INFINITY) <= static_cast<float>(box.upper[k]));
      }
    }
  }
  SECTION("an empty box stays empty") { CHECK(roundOutward(Aabb<double>{}).empty()); }
}

}  // namespace rtu
