// `rtusim compare`'s float64 reference (explore/reference_frame.h) against the oracle it must
// equal, closestHit over every triangle, on the same rays; and the agreement measures of an image
// against it (explore/frame_agreement.h) on frames made by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "explore/frame_agreement.h"
#include "explore/reference_frame.h"
#include "geometry/ray_sets.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/voxel_faces.h"

namespace rtu {
namespace {

void checkAgainstOracle(const TriangleMesh& mesh, const std::vector<Ray>& rays) {
  const ReferenceTracer tracer(mesh);
  size_t hits = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    INFO("ray " << i);
    const auto expected = closestHit(mesh, rays[i], 0, INFINITY);
    const auto found = tracer.trace(rays[i]);
    REQUIRE(found.has_value() == expected.has_value());
    if (!expected) continue;
    ++hits;
    CHECK(found->triangle == expected->triangle);
    CHECK(found->t == expected->t);
  }
  CHECK(hits > rays.size() / 4);  // the rays test something
}

// Voxel faces (many triangles sharing planes and edges: ties) and the same placed, turned.
TEST_CASE("compare reference: the BVH finds closestHit's hits", "[compare]") {
  const TriangleMesh faces = voxelFaces(*makeProceduralScene("menger", 4));
  ModelPlacement placement;
  placement.translation = {0.3, -0.2, 0.5};
  placement.rotation = rotationFromEulerDegrees({20, 35, 10});
  placement.scale = glm::dvec3(1.7);
  for (const TriangleMesh& mesh : {faces, placedMesh(faces, placement)}) {
    const Aabb<double> box = meshBounds(mesh);
    std::vector<Ray> rays = viewRays(box, 3, 16, 12);
    for (const Ray& ray : aimedRays(mesh, 400, 7)) rays.push_back(ray);
    for (const Ray& ray : randomRays(box, 400, 9)) rays.push_back(ray);
    checkAgainstOracle(mesh, rays);
  }
}

// A 2x1 frame looking down -z from z = 5 at the cube [-1,1]^3, 10 degrees high (20 wide).
Camera twoPixels() {
  Camera camera;
  camera.position = {0, 0, 5};
  camera.lookAt = {0, 0, 0};
  camera.width = 2;
  camera.height = 1;
  camera.verticalFovDegrees = 10;
  return camera;
}

TEST_CASE("compare agreement: verdicts and depth error by hand", "[compare]") {
  const Camera camera = twoPixels();
  std::vector<FrameHit> frame(2);
  std::vector<std::optional<OracleHit>> reference(2);
  const ObjectRule triangles{false, 0};
  // Pixel 0: both hit triangle 3, t 4.0 and 4.25; pixel 1: both miss.
  frame[0] = FrameHit{true, 4.25, 3};
  reference[0] = OracleHit{4.0, 0, 0, 3};
  ImageAgreement a = imageAgreement(camera, frame, reference, triangles);
  CHECK(a.pixels == 2);
  CHECK(a.bothHit == 1);
  CHECK(a.bothMiss == 1);
  CHECK(a.hitMissDiffer() == 0);
  CHECK(a.otherObject == 0);
  CHECK(a.meanDepthError == 0.25);
  // Pixel 1 hits where the reference misses; pixel 0 hits another triangle.
  frame[1] = FrameHit{true, 4.0, 5};
  reference[0]->triangle = 2;
  a = imageAgreement(camera, frame, reference, triangles);
  CHECK(a.falseHits == 1);
  CHECK(a.otherObject == 1);
  CHECK(a.bothHit == 1);
  // Missed: the reference hits pixel 1 too; the frame misses pixel 0.
  frame[0].hit = false;
  reference[1] = OracleHit{4.5, 0, 0, 5};
  a = imageAgreement(camera, frame, reference, triangles);
  CHECK(a.missedHits == 1);
  CHECK(a.bothHit == 1);
  CHECK(a.meanDepthError == 0.5);
  CHECK(pixelVerdicts(camera, frame, reference, triangles) ==
        std::vector<PrecisionVerdict>{PrecisionVerdict::MissedHit, PrecisionVerdict::Agree});
}

// Pixel 1 of the 2x1 frame looks down from z = 5 right of the centre line, in the plane y = 0.
// At the distance where it meets the cube's face z = 1 it enters the cube's top; a hundredth of a
// cell on, it is in the cell with z in [0, 1], x in [0, 1] and (y = 0 exactly) y in [0, 1]: at
// depth 1 (two cells a side) the cell (1, 1, 1), packed x << 42 | y << 21 | z.
TEST_CASE("compare agreement: the SVO's object is the cell the ray enters", "[compare]") {
  const Camera camera = twoPixels();
  const Ray ray = camera.primaryRay(1, 0);
  const glm::dvec3 d = glm::normalize(ray.direction);
  // The distance to the plane z = 1 along the pixel's ray: (5 - 1) / -d.z.
  const double t = 4 / -d.z;
  const glm::dvec3 p = ray.origin + t * d;
  REQUIRE(p.x > 0);
  REQUIRE(p.x < 1);
  REQUIRE(p.y == 0);
  CHECK(voxelAt(camera, 1, t, 1) == ((uint64_t(1) << 42) | (uint64_t(1) << 21) | 1));
  // Past the cube's centre plane z = 0 the ray is in the cell below.
  CHECK(voxelAt(camera, 1, 5 / -d.z + 0.1, 1) == ((uint64_t(1) << 42) | (uint64_t(1) << 21)));
}

}  // namespace
}  // namespace rtu
