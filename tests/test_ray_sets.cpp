// Ray sets for checking traversals against the oracle (geometry/ray_sets.h): counts, unit
// directions, views aimed at the box, aimed rays through vertices and edge midpoints, random rays
// inside the box, and the same rays for the same seed.
#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include "geometry/ray_sets.h"
#include "geometry/triangle_oracle.h"

namespace rtu {
namespace {

// The closed unit cube [0, 2]^3 as 12 triangles.
TriangleMesh cube() {
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i)
    mesh.vertices.push_back({2.0 * (i & 1), (i & 2) * 1.0, (i & 4) * 0.5});
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}

bool unitLength(const Ray& ray) { return std::abs(glm::length(ray.direction) - 1) < 1e-12; }

}  // namespace

TEST_CASE("Ray sets: the cube's bounds are its corners", "[ray_sets]") {
  const Aabb<double> box = meshBounds(cube());
  CHECK(box.lower == glm::dvec3(0));
  CHECK(box.upper == glm::dvec3(2));
}

TEST_CASE("Ray sets: views from outside the box, the middle ray through its centre", "[ray_sets]") {
  const Aabb<double> box = meshBounds(cube());
  const std::vector<Ray> rays = viewRays(box, 4, 5, 3);
  REQUIRE(rays.size() == 4 * 5 * 3);
  for (int view = 0; view < 4; ++view) {
    const Ray& middle = rays[view * 15 + 7];  // row 1, column 2
    CHECK_FALSE(box.contains(Aabb<double>{middle.origin, middle.origin}));
    const glm::dvec3 toCentre = glm::normalize(box.centre() - middle.origin);
    CHECK(glm::length(middle.direction - toCentre) < 1e-12);
    for (int i = 0; i < 15; ++i) CHECK(rays[view * 15 + i].origin == middle.origin);
  }
  CHECK(rays[0].origin != rays[15].origin);
  for (const Ray& ray : rays) CHECK(unitLength(ray));
}

TEST_CASE("Ray sets: aimed rays pass through vertices and edge midpoints", "[ray_sets]") {
  const TriangleMesh mesh = cube();
  const std::vector<Ray> rays = aimedRays(mesh, 200, 7);
  REQUIRE(rays.size() == 200);
  const double distance = std::sqrt(12.0);  // the cube's diagonal
  for (size_t i = 0; i < rays.size(); ++i) {
    const glm::dvec3 target = rays[i].origin + distance * rays[i].direction;
    // Every coordinate of a vertex is 0 or 2; of an edge midpoint, 0, 1 or 2.
    for (int k = 0; k < 3; ++k) {
      const double c = target[k];
      CHECK(std::abs(c - std::round(c)) < 1e-12);
      if (i % 2 == 0) CHECK(std::abs(c - 1) > 0.5);
    }
    CHECK(unitLength(rays[i]));
  }
}

TEST_CASE("Ray sets: every aimed ray through the cube's inside hits it no later than its target",
          "[ray_sets]") {
  const TriangleMesh mesh = cube();
  const double distance = std::sqrt(12.0);
  const auto inside = [](const glm::dvec3& p) {
    return glm::all(glm::greaterThan(p, glm::dvec3(0))) &&
           glm::all(glm::lessThan(p, glm::dvec3(2)));
  };
  int crossing = 0;
  for (const Ray& ray : aimedRays(mesh, 500, 11)) {
    // A line that only touches the cube at its target may pass beside it once rounded.
    const glm::dvec3 target = ray.origin + distance * ray.direction;
    if (!inside(target + 1e-6 * ray.direction) && !inside(target - 1e-6 * ray.direction)) continue;
    ++crossing;
    const auto hit = closestHit(mesh, ray, 0, 1e9);
    REQUIRE(hit);
    CHECK(hit->t <= distance * (1 + 1e-12));
  }
  CHECK(crossing > 200);  // 245: about half the lines through a boundary point
}

TEST_CASE("Ray sets: random rays start inside the box and spread evenly", "[ray_sets]") {
  const Aabb<double> box{{-1, 0, 2}, {1, 3, 2.5}};
  const std::vector<Ray> rays = randomRays(box, 10000, 3);
  glm::dvec3 mean(0);
  for (const Ray& ray : rays) {
    CHECK(box.contains(Aabb<double>{ray.origin, ray.origin}));
    CHECK(unitLength(ray));
    mean += ray.direction / double(rays.size());
  }
  CHECK(glm::length(mean) < 0.05);
}

TEST_CASE("Ray sets: a seed gives the same rays, another seed others", "[ray_sets]") {
  const TriangleMesh mesh = cube();
  const auto first = aimedRays(mesh, 10, 5), again = aimedRays(mesh, 10, 5);
  const auto other = aimedRays(mesh, 10, 6);
  for (size_t i = 0; i < 10; ++i) {
    CHECK(first[i].origin == again[i].origin);
    CHECK(first[i].direction == again[i].direction);
  }
  CHECK(first[0].direction != other[0].direction);
}

TEST_CASE("Ray sets: nothing to aim at is an error", "[ray_sets]") {
  CHECK_THROWS_WITH(viewRays(Aabb<double>{}, 1, 1, 1), "viewRays: the box is empty");
  CHECK_THROWS_WITH(aimedRays(TriangleMesh{}, 1, 0), "aimedRays: the mesh has no triangle");
}

}  // namespace rtu
