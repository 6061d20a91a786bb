// The triangle kinds' oracle (geometry/triangle_oracle.h): the nearest of several hits, ties to
// the lowest index, the t range, and no crack along a quad's shared diagonal.
#include <catch2/catch.hpp>

#include <random>

#include "geometry/triangle_oracle.h"

namespace rtu {
namespace {

// Unit right triangles in the planes z = heights[i], in that order.
TriangleMesh stacked(const std::vector<double>& heights) {
  TriangleMesh mesh;
  for (double z : heights) {
    const uint32_t first = static_cast<uint32_t>(mesh.vertices.size());
    mesh.vertices.push_back({0, 0, z});
    mesh.vertices.push_back({1, 0, z});
    mesh.vertices.push_back({0, 1, z});
    mesh.triangles.push_back({first, first + 1, first + 2});
  }
  return mesh;
}

Ray down(double x, double y) { return Ray{{x, y, 4}, {0, 0, -1}}; }

}  // namespace

TEST_CASE("Triangle oracle: the nearest hit, ties to the lowest index", "[triangle_oracle]") {
  const TriangleMesh mesh = stacked({0, 2, 1, 2});
  const auto hit = closestHit(mesh, down(0.25, 0.5), 0, 100);
  REQUIRE(hit);
  CHECK(hit->triangle == 1);  // z = 2, before its twin at index 3
  CHECK(hit->t == 2.0);
  CHECK(hit->u == 0.25);
  CHECK(hit->v == 0.5);
  SECTION("from the other side the nearest is another") {
    const auto below = closestHit(mesh, Ray{{0.25, 0.5, -1}, {0, 0, 1}}, 0, 100);
    REQUIRE(below);
    CHECK(below->triangle == 0);
    CHECK(below->t == 1.0);
  }
  SECTION("the t range bounds the hits, inclusive") {
    CHECK(closestHit(mesh, down(0.25, 0.5), 2.5, 100)->triangle == 2);  // z = 1 at t = 3
    CHECK(closestHit(mesh, down(0.25, 0.5), 0, 2)->triangle == 1);
    CHECK_FALSE(closestHit(mesh, down(0.25, 0.5), 0, 1.5));
    CHECK_FALSE(closestHit(mesh, down(0.25, 0.5), 4.5, 100));
  }
  SECTION("outside every triangle, or no triangle") {
    CHECK_FALSE(closestHit(mesh, down(0.75, 0.75), 0, 100));
    CHECK_FALSE(closestHit(TriangleMesh{}, down(0.25, 0.5), 0, 100));
  }
}

TEST_CASE("Triangle oracle: no ray through a quad's diagonal misses it", "[triangle_oracle]") {
  // A slanted unit quad split along its diagonal; rays from scattered origins aimed at points of
  // the diagonal, in float64, must all hit one of its two triangles.
  TriangleMesh quad;
  quad.vertices = {{0, 0, 0}, {1, 0, 0.3}, {1, 1, 0.5}, {0, 1, 0.2}};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(-2, 3);
  for (int i = 1; i < 100; ++i) {
    const double s = i / 100.0;
    const glm::dvec3 target = (1 - s) * quad.vertices[0] + s * quad.vertices[2];
    const glm::dvec3 origin{uniform(random), uniform(random), 3};
    INFO("diagonal point " << s);
    CHECK(closestHit(quad, Ray{origin, target - origin}, 0, 10));
  }
}

}  // namespace rtu
