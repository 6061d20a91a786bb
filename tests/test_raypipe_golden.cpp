// The ray pipe's simple shader (raypipe/simple_shader.h: R1 simple_shade_unit.sv's colours) and
// its golden frame (raypipe/raypipe_golden.h) against the independent oracle
// (geometry/triangle_oracle.h), which shares no traversal code, on a small mesh.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "explore/accel_build.h"
#include "geometry/triangle_oracle.h"
#include "kinds/kd/trayracer_scene.h"
#include "raypipe/raypipe_camera.h"
#include "raypipe/raypipe_golden.h"
#include "raypipe/simple_shader.h"

namespace rtu {
namespace {

// Two octahedra, one partly behind the other: no face flat on an axis, so none lies on a split.
TriangleMesh twoOctahedra() {
  TriangleMesh mesh;
  const auto add = [&mesh](glm::dvec3 centre, double radius) {
    const auto first = static_cast<uint32_t>(mesh.vertices.size());
    for (int axis = 0; axis < 3; ++axis)
      for (double sign : {1.0, -1.0}) {
        glm::dvec3 v = centre;
        v[axis] += sign * radius;
        mesh.vertices.push_back(v);
      }
    // Vertices +x -x +y -y +z -z; a face per octant.
    for (uint32_t x : {0u, 1u})
      for (uint32_t y : {2u, 3u})
        for (uint32_t z : {4u, 5u}) mesh.triangles.push_back({first + x, first + y, first + z});
  };
  add({0.1, 0.05, 0.2}, 0.8);
  add({0.7, -0.3, 1.1}, 0.9);
  return mesh;
}

Ray asDouble(const KdRay& ray) {
  return Ray{glm::dvec3(ray.origin[0], ray.origin[1], ray.origin[2]),
             glm::dvec3(ray.direction[0], ray.direction[1], ray.direction[2])};
}

double edgeMargin(double u, double v) { return std::min({u, v, 1 - u - v}); }

}  // namespace

TEST_CASE("The simple shader's palette is the RTL's", "[raypipe]") {
  // simple_shade_unit.sv calc_color and defines.sv's TRI_*_COLOR, MISS_COLOR.
  CHECK(simpleShade(true, false, 0) == 0xF81F);  // 11111_000000_11111
  CHECK(simpleShade(true, true, 1) == 0xF81F);   // a box miss wins
  CHECK(simpleShade(false, false, 0) == 0xFFFF);
  CHECK(simpleShade(false, true, 4) == 0xAD55);  // 10101_101010_10101
  CHECK(simpleShade(false, true, 5) == 0xFFE0);  // 11111_111111_00000
  CHECK(simpleShade(false, true, 6) == 0x0600);  // 00000_110000_00000
  CHECK(simpleShade(false, true, 7) == 0xF800);  // 11111_000000_00000
  CHECK(rgb888(0xFFFF) == std::array<uint8_t, 3>{255, 255, 255});
  CHECK(rgb888(0xAD55) == std::array<uint8_t, 3>{173, 170, 173});  // 21, 42, 21 expanded
  CHECK(rgb888(0x0600) == std::array<uint8_t, 3>{0, 195, 0});
}

TEST_CASE("The golden frame finds the oracle's hits on a small mesh", "[raypipe]") {
  const TriangleMesh mesh = twoOctahedra();
  AccelSpec spec;
  spec.structure = "kdtree";
  const AccelBuild build = buildAccel(mesh, spec);
  TriangleMesh hardware = mesh;
  for (auto& v : hardware.vertices) v = toHardwareSpace(v);

  Camera camera;
  camera.position = {-1.2, 0.8, -1.6};
  camera.lookAt = {0.3, -0.1, 0.5};
  const std::vector<PrimaryRay> rays = primaryRays(raypipeCameraOf(camera), prgLevelSize(2));
  const RaypipeGoldenFrame frame = runGoldenFrame(build.words, rays, RaypipeConfig{});
  REQUIRE(frame.pixels.size() == 80 * 60);

  int same = 0, nearEdge = 0, unexplained = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const RaypipePixel& p = frame.pixels[i];
    CHECK(p.pixel.pixelId == rays[i].pixel.pixelId);
    const auto oracle = closestHit(hardware, asDouble(rays[i].ray), 0, INFINITY);
    if (p.hit == oracle.has_value() && (!p.hit || p.primitive == oracle->triangle)) {
      ++same;
      if (p.hit) CHECK(p.t == Approx(oracle->t).epsilon(1e-4));
    } else if ((oracle && edgeMargin(oracle->u, oracle->v) < 1e-3) ||
               (p.hit && edgeMargin(p.u, p.v) < 1e-3)) {
      ++nearEdge;
    } else {
      ++unexplained;
    }
  }
  INFO("same " << same << ", near an edge " << nearEdge << "; hits " << frame.totals.hits
               << ", box misses " << frame.totals.boxMisses);
  CHECK(unexplained == 0);
  CHECK(same > 4700);  // measured: all 4,800 the same
  CHECK(frame.totals.rays == 4800);
  CHECK(frame.totals.hits > 500);  // measured 888 hits and 956 box misses
  CHECK(frame.totals.hits < 4000);
  CHECK(frame.totals.boxMisses > 0);
  CHECK(frame.totals.triangleTests >= frame.totals.hits);
}

TEST_CASE("The golden frame takes the pipe's stack depth", "[raypipe]") {
  AccelSpec spec;
  spec.structure = "kdtree";
  const AccelBuild build = buildAccel(twoOctahedra(), spec);
  Camera camera;
  camera.lookAt = {0.3, -0.1, 0.5};
  const std::vector<PrimaryRay> rays = primaryRays(raypipeCameraOf(camera), prgLevelSize(1));
  RaypipeConfig shallow;
  shallow.shortStackDepth = 1;
  const RaypipeGoldenFrame one = runGoldenFrame(build.words, rays, shallow);
  const RaypipeGoldenFrame four = runGoldenFrame(build.words, rays, RaypipeConfig{});
  CHECK(one.totals.hits == four.totals.hits);
  CHECK(one.totals.restarts >= four.totals.restarts);
  CHECK(one.totals.dropped >= four.totals.dropped);
  CHECK(kdTraversalConfig(shallow).stackDepth == 1);
}

}  // namespace rtu
