#pragma once
// What every BVH builder starts from: each triangle's box and box centre in double, after checking
// that the mesh can be built at all (the builders' own guard; meshes from files are checked with
// clear messages first, geometry/mesh_checks.h).

#include <string>
#include <vector>

#include "geometry/aabb.h"
#include "geometry/triangle_mesh.h"

namespace rtu {

struct BuildPrimitives {
  std::vector<Aabb<double>> boxes;  // by triangle
  std::vector<glm::dvec3> centres;  // each box's centre

  // The box of boxes[refs[first .. first + count - 1]].
  Aabb<double> boxOf(const std::vector<uint32_t>& refs, uint32_t first, uint32_t count) const;
};

// Throws std::invalid_argument naming `builder` for a mesh without triangles, with more than
// 2^32 - 1, a vertex index out of range, or a coordinate that is not finite or beyond 2^1000 in
// magnitude (every sum, difference and area of the builders then stays finite).
BuildPrimitives buildPrimitives(const TriangleMesh& mesh, const std::string& builder);

// The first axis of greatest extent: x, then y, then z.
int widestAxis(const Aabb<double>& box);

}  // namespace rtu
