#pragma once
// Rays to check a triangle kind's traversal against the oracle (triangle_oracle.h) on a mesh:
// coherent primary rays from several views, rays aimed exactly at vertices and edge midpoints
// (where a test that is not watertight loses hits), and incoherent random rays. Sampling uses its
// own mapping of a seeded std::mt19937_64, so a seed gives the same rays with any standard library.

#include <cstdint>
#include <vector>

#include "geometry/aabb.h"
#include "geometry/ray.h"
#include "geometry/triangle_mesh.h"

namespace rtu {

// The box of the mesh's vertices (those its triangles use).
Aabb<double> meshBounds(const TriangleMesh& mesh);

// Pinhole views of `box` from `views` eyes spaced evenly around it, slightly above, each
// width x height rays through an image plane as wide as the box's diagonal at its centre; rays in
// view order, then row-major. Directions are unit length.
std::vector<Ray> viewRays(const Aabb<double>& box, int views, int width, int height);

// `count` rays through a vertex or an edge midpoint of a random triangle of `mesh` (half each),
// from a random direction, starting one box diagonal before it. Directions are unit length.
std::vector<Ray> aimedRays(const TriangleMesh& mesh, size_t count, uint64_t seed);

// The same rays with what each is aimed at: the vertex a (b == a) or the midpoint of the edge
// (a, b), as indices into the mesh's vertices.
struct AimedRay {
  Ray ray;
  uint32_t a = 0, b = 0;
  bool atVertex() const { return a == b; }
};
std::vector<AimedRay> aimedFeatureRays(const TriangleMesh& mesh, size_t count, uint64_t seed);

// `count` rays from points uniform in `box` in directions uniform on the sphere (unit length).
std::vector<Ray> randomRays(const Aabb<double>& box, size_t count, uint64_t seed);

}  // namespace rtu
