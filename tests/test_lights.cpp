// Shadow rays' area lights (inputs/light.h, issue 32): points drawn uniformly over a rectangle or a
// disc by the seeded sampler, and a hit's shadow rays light by light, an area light's samples in
// turn.

#include <catch2/catch.hpp>

#include <cmath>

#include <glm/geometric.hpp>

#include "inputs/light.h"
#include "inputs/secondary_rays.h"

namespace rtu {

TEST_CASE("A rectangular light's samples cover it uniformly", "[lights]") {
  // Edges 2 along x and 1 along z about (0, 3, 0): each sample's coordinates along the edges lie
  // in [-1/2, 1/2), their means near 0 (4,000 samples: 0.0046 standard error) and the share in
  // the quarter a > 0, b > 0 near 1/4.
  const Light light{Light::Shape::Rectangle, {0, 3, 0}, {2, 0, 0}, {0, 0, 1}};
  RaySampler sampler(5, 0);
  double sumA = 0, sumB = 0;
  int quarter = 0;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 p = light.sample(sampler);
    CHECK(p.y == 3.0);
    const double a = p.x / 2, b = p.z;
    REQUIRE(std::abs(a) <= 0.5);
    REQUIRE(std::abs(b) <= 0.5);
    sumA += a;
    sumB += b;
    quarter += a > 0 && b > 0;
  }
  CHECK(std::abs(sumA / n) < 0.02);
  CHECK(std::abs(sumB / n) < 0.02);
  CHECK(std::abs(quarter / double(n) - 0.25) < 0.03);
}

TEST_CASE("A disc light's samples cover it uniformly", "[lights]") {
  // Uniform over the disc's area: every sample in its plane and within its radius, half of them
  // within r / sqrt(2), the mean near the centre.
  const glm::dvec3 centre(1, 2, 3), axis = glm::normalize(glm::dvec3(1, 1, 0));
  Light light{Light::Shape::Disc, centre};
  light.normal = axis;
  light.radius = 0.5;
  RaySampler sampler(9, 3);
  glm::dvec3 sum(0.0);
  int inner = 0;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 d = light.sample(sampler) - centre;
    REQUIRE(std::abs(glm::dot(d, axis)) < 1e-12);
    REQUIRE(glm::length(d) <= 0.5 + 1e-12);
    inner += glm::length(d) < 0.5 / std::sqrt(2.0);
    sum += d;
  }
  CHECK(std::abs(inner / double(n) - 0.5) < 0.03);
  CHECK(glm::length(sum / double(n)) < 0.02);
  RaySampler again(9, 3);
  RaySampler same(9, 3);
  CHECK(light.sample(again) == light.sample(same));
}

TEST_CASE("A hit's shadow rays go to each light's samples in turn", "[lights]") {
  // A rectangle sampled 4 times and a point light: 5 rays a hit, ids pixel * 5 + k; rays 0-3 end
  // on the rectangle (t = 1 at the light), at 4 different points, ray 4 at the point light.
  SecondarySettings settings;
  settings.type = RayType::Shadow;
  settings.lightSamples = 4;
  settings.selfOffset = 0;
  settings.lights = {Light{Light::Shape::Rectangle, {0, 3, 0}, {1, 0, 0}, {0, 0, 1}},
                     Light::point({0.5, 2, 0.5})};
  REQUIRE(settings.raysPerHit() == 5);
  SurfaceHit hit;
  hit.pixel = 7;
  hit.point = {0.1, 0.0, -0.2};
  hit.normal = {0, 1, 0};
  hit.incoming = {0, -1, 0};
  const std::vector<RayRecord> rays = spawnSecondaryRays({hit}, settings, 0);
  REQUIRE(rays.size() == 5);
  std::vector<glm::dvec3> ends;
  for (uint32_t k = 0; k < 5; ++k) {
    const RayRecord& ray = rays[k];
    CHECK(ray.id == 7 * 5 + k);
    CHECK(ray.span == RaySpan::AnyHit);
    ends.push_back(glm::dvec3(ray.origin[0] + ray.direction[0], ray.origin[1] + ray.direction[1],
                              ray.origin[2] + ray.direction[2]));
  }
  for (int k = 0; k < 4; ++k) {
    CHECK(ends[k].y == Approx(3.0));
    CHECK(std::abs(ends[k].x) <= 0.5 + 1e-6);
    CHECK(std::abs(ends[k].z) <= 0.5 + 1e-6);
    for (int j = 0; j < k; ++j) CHECK(glm::length(ends[k] - ends[j]) > 1e-3);
  }
  CHECK(glm::length(ends[4] - glm::dvec3(0.5, 2, 0.5)) < 1e-6);
  // A light below the face gives no ray: the point is in its own shadow.
  settings.lights = {Light::point({0, -1, 0})};
  CHECK(spawnSecondaryRays({hit}, settings, 0).empty());
}

}  // namespace rtu
