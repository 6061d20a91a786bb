// Ray set-up (thesis 6.2.1) and traversal in all eight octants and along the axes, on a sphere
// that is symmetric under every axis flip.
#include <catch2/catch.hpp>

#include <cmath>

#include "kinds/svo/golden_model.h"
#include "kinds/svo/ray_setup.h"
#include "kinds/svo/reference_model.h"
#include "kinds/svo/svo_builder.h"

using namespace rtu;

namespace {

// Solid where the voxel centre lies within `radius` of the origin.
class CentredSphere : public VoxelSource {
 public:
  CentredSphere(int depth, double radius) : depth_(depth), radius_(radius) {}
  int depth() const override { return depth_; }
  Occupancy classify(const OctreeNode& node) const override {
    if (node.level < depth_) return Occupancy::Mixed;
    const glm::dvec3 c = node.centre();
    return c.x * c.x + c.y * c.y + c.z * c.z <= radius_ * radius_ ? Occupancy::Full
                                                                  : Occupancy::Empty;
  }

 private:
  int depth_;
  double radius_;
};

const SvoBuild& sphere() {
  static const SvoBuild build = buildSvo(CentredSphere(6, 0.8));
  return build;
}

}  // namespace

TEST_CASE("Ray set-up mirrors negative components and ORs their sign bits", "[rays]") {
  const Ray ray{{0.5, -0.25, 3.0}, {-1.0, 0.0, -2.0}};
  const RayParameters<double> p = computeRayParameters<double>(ray, 1e-4);
  REQUIRE(p.a == 0b101);
  const double dx = 1.0 / std::sqrt(5.0);
  const double dz = 2.0 / std::sqrt(5.0);
  REQUIRE(p.t0[0] == Approx((-1.0 + 0.5) / dx));  // mirrored origin -0.5
  REQUIRE(p.t1[0] == Approx((1.0 + 0.5) / dx));
  REQUIRE(p.t0[1] == Approx((-1.0 + 0.25) / 1e-4));  // zero replaced by epsilon, not mirrored
  REQUIRE(p.t0[2] == Approx((-1.0 + 3.0) / dz));
  REQUIRE(p.t1[2] == Approx((1.0 + 3.0) / dz));

  const TValueRecord job = makeTValueRecord(9, ray, 17);
  REQUIRE(job.a == 0b101);
  REQUIRE(job.idWord() == (9u | 5u << 28));
  REQUIRE(job.root == 17);
  REQUIRE(bitsToFloat(job.t0Bits[0]) == Approx(p.t0[0]));
}

TEST_CASE("All eight octants give the same traversal on a symmetric scene", "[rays]") {
  GoldenModel model(sphere().image.memory(), GoldenConfig{});
  const glm::dvec3 eye(2.1, 1.7, 2.5);
  const glm::dvec3 target(0.05, -0.1, 0.12);
  TraversalResult first;
  for (int octant = 0; octant < 8; ++octant) {
    glm::dvec3 flip(octant & 1 ? -1 : 1, octant & 2 ? -1 : 1, octant & 4 ? -1 : 1);
    const Ray ray{eye * flip, (target - eye) * flip};
    const TraversalResult result = model.trace(makeTValueRecord(0, ray, 0));
    INFO("octant " << octant);
    REQUIRE(result.hit);
    REQUIRE(result.idWord >> 28 == static_cast<uint32_t>(7 - octant));  // a: negative directions
    if (octant == 0) {
      first = result;
    } else {
      REQUIRE(result.tHit == first.tHit);
      REQUIRE(result.normal == first.normal);
      REQUIRE(result.cost == first.cost);
    }
  }
}

TEST_CASE("Axis-parallel rays hit the sphere where geometry says", "[rays]") {
  GoldenModel model(sphere().image.memory(), GoldenConfig{});
  ReferenceModel reference(sphere().image.memory());
  const double voxel = 2.0 / 64;
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {1.0, -1.0}) {
      glm::dvec3 origin(0.03, -0.05, 0.02);
      origin[axis] = -3.0 * sign;
      glm::dvec3 direction(0.0);
      direction[axis] = sign;
      const Ray ray{origin, direction};
      const TraversalResult result = model.trace(makeTValueRecord(0, ray, 0));
      const ReferenceResult exact = reference.trace(ray, 0);
      INFO("axis " << axis << " sign " << sign);
      REQUIRE(result.hit);
      REQUIRE(result.normal[axis] == 0x10000);  // entered through the face across the ray
      const double t = result.tHit / 65536.0;
      REQUIRE(std::abs(t - (3.0 - 0.8)) < 2 * voxel);
      REQUIRE(exact.hit);
      REQUIRE(std::abs(t - exact.tHit) < 1e-3);
    }
  }
}
