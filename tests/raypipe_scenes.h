#pragma once
// The ray pipe's test scenes and rays (issue 29), shared by the per-cycle reference's tests, the
// timed model's and the ray pipe's benchmark: pbrt-built scenes (a few triangles at different
// depths, a sphere-like mesh, one triangle), rays from around a scene's box, and the primary rays
// of R1's PRG at a resolution level.

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "kinds/kd/kd_image.h"
#include "kinds/kd/kd_kind.h"
#include "kinds/kd/pbrt_kd_builder.h"
#include "raypipe/raypipe_run.h"

namespace rtu {

// A scene of world-space triangles (three corners each) built as R1's software builds it.
inline KdImage builtImage(const std::vector<glm::dvec3>& corners) {
  const KdBuild build = buildPbrtKd(pbrtTriangleBoxes(corners), PbrtKdParameters{});
  const std::vector<glm::dvec3> normals(corners.size() / 3, glm::dvec3(0, 0, 1));
  return layOutKd(makeTrayRacerScene(build, corners, normals, {}));
}

// A sphere-like mesh: a UV sphere of radius 1 at `centre`, `rings` x `segments` quads.
inline std::vector<glm::dvec3> sphereCorners(glm::dvec3 centre, int rings, int segments) {
  const double pi = std::acos(-1.0);
  auto at = [&](int ring, int segment) {
    const double theta = pi * ring / rings, phi = 2 * pi * segment / segments;
    return centre + glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                               std::sin(theta) * std::sin(phi));
  };
  std::vector<glm::dvec3> corners;
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const glm::dvec3 a = at(r, s), b = at(r + 1, s), c = at(r + 1, s + 1), d = at(r, s + 1);
      if (r > 0) corners.insert(corners.end(), {a, b, d});
      if (r + 1 < rings) corners.insert(corners.end(), {b, c, d});
    }
  return corners;
}

// A few triangles at different depths, so rays cross several leaves.
inline std::vector<glm::dvec3> fewTriangles() {
  std::vector<glm::dvec3> corners;
  for (int i = 0; i < 6; ++i) {
    const double z = 0.5 * i, x = 0.3 * (i % 3), y = 0.2 * (i % 2);
    corners.insert(corners.end(), {{x, y, z}, {x + 1.5, y, z + 0.1}, {x, y + 1.5, z + 0.2}});
  }
  return corners;
}

inline KdSections sectionsOfImage(const KdImage& image) {
  return sectionsOf(decodeKdHeader(image.words.data()));
}

// Rays in hardware space: from outside the box towards points inside it, a few away from it, and
// the PRG's kind (unnormalised, |d| >= 240, so the as-built clamp gives t_max = 1).
inline std::vector<RaypipeCycleRay> mixedRays(const KdImage& image, int count, uint32_t seed) {
  const std::array<float, 6> box = sectionsOfImage(image).box;
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  auto inside = [&] {
    return std::array<float, 3>{box[0] + unit(random) * (box[3] - box[0]),
                                box[1] + unit(random) * (box[4] - box[1]),
                                box[2] + unit(random) * (box[5] - box[2])};
  };
  std::vector<RaypipeCycleRay> rays;
  for (int i = 0; i < count; ++i) {
    const std::array<float, 3> target = inside();
    std::array<float, 3> origin{};
    for (int a = 0; a < 3; ++a)
      origin[a] = box[a] - 1.5f * (box[a + 3] - box[a]) + unit(random) * 4 * (box[a + 3] - box[a]);
    KdRay ray;
    ray.origin = origin;
    const float scale = (i % 3 == 0) ? 240.0f : 1.0f;
    for (int a = 0; a < 3; ++a) ray.direction[a] = (target[a] - origin[a]) * scale;
    if (i % 7 == 3)  // away from the box
      for (int a = 0; a < 3; ++a) ray.direction[a] = -ray.direction[a];
    rays.push_back(RaypipeCycleRay{ray, static_cast<uint32_t>(i)});
  }
  return rays;
}

// One triangle in the plane z = 1 of hardware space (x and y swapped from world: the corners are
// given in world space), so the root is a leaf.
inline KdImage oneTriangle() {
  return builtImage({{0, 0, 1}, {0, 2, 1}, {2, 0, 1}});  // hardware: (0,0), (2,0), (0,2)
}

inline KdRay downZ(float x, float y) { return KdRay{{x, y, 0}, {0, 0, 1}, false}; }

// Primary rays as R1's PRG makes them (PRG/primary_ray_generator.sv, prg_pl.sv; specs/001 §2.2),
// enough for frame figures: 20x15 blocks in Z order (x from the block counter's even bits, y from
// its odd bits, the top block row first), x fastest and y from the block's top row down inside a
// block, pixelID = (rows - 1 - y) cols + x, dir = U (x pw - 320) + V (y pw - 240) + W 240 in
// binary32 in the RTL's order, from E = INIT_CAM with U, V, W the axes.
inline std::vector<RaypipeCycleRay> prgRays(int level) {
  const int cols = 20 << level, rows = 15 << level, blocks = 1 << (2 * level);
  const float pw = static_cast<float>(32 >> level);
  const int maxYIndex = (1 << level) - 1;
  std::vector<RaypipeCycleRay> rays;
  for (int block = 0; block < blocks; ++block) {
    int xIndex = 0, yIndex = 0;
    for (int b = 0; b < level; ++b) {
      xIndex |= ((block >> (2 * b)) & 1) << b;
      yIndex |= ((block >> (2 * b + 1)) & 1) << b;
    }
    for (int yIn = 14; yIn >= 0; --yIn)
      for (int xIn = 0; xIn < 20; ++xIn) {
        const int x = 20 * xIndex + xIn, y = 15 * (maxYIndex - yIndex) + yIn;
        const float u = add32(mul32(static_cast<float>(x), pw), -320.0f);
        const float v = add32(mul32(static_cast<float>(y), pw), -240.0f);
        KdRay ray;
        ray.origin = {1.125f, 1.125f, -1.25f};
        // U = (1, 0, 0), V = (0, 1, 0), W = (0, 0, 1): each component's three products, summed
        // in the RTL's order
        const float uc[3] = {1, 0, 0}, vc[3] = {0, 1, 0}, wc[3] = {0, 0, 1};
        for (int a = 0; a < 3; ++a)
          ray.direction[a] = add32(add32(mul32(u, uc[a]), mul32(v, vc[a])), mul32(wc[a], 240.0f));
        rays.push_back(RaypipeCycleRay{ray, static_cast<uint32_t>((rows - 1 - y) * cols + x)});
      }
  }
  return rays;
}

// A sphere-like mesh of 80 triangles in front of the camera.
inline KdImage frameScene() { return builtImage(sphereCorners({1.125, 1.125, 1.5}, 5, 10)); }

}  // namespace rtu
