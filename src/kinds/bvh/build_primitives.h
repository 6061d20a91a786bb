#pragma once
// What every BVH builder starts from: each primitive's box and box centre in double. A mesh's
// primitives are its triangles, checked first that the mesh can be built at all (the builders' own
// guard; meshes from files are checked with clear messages first, geometry/mesh_checks.h); a
// two-level BVH's top level is built over its instances' world boxes (two_level.h).

#include <string>
#include <vector>

#include "geometry/aabb.h"
#include "geometry/triangle_mesh.h"

namespace rtu {

struct BuildPrimitives {
  std::vector<Aabb<double>> boxes;  // by primitive (triangle or instance)
  std::vector<glm::dvec3> centres;  // each box's centre

  // The box of boxes[refs[first .. first + count - 1]].
  Aabb<double> boxOf(const std::vector<uint32_t>& refs, uint32_t first, uint32_t count) const;
};

// Throws std::invalid_argument naming `builder` for a mesh without triangles, with more than
// 2^32 - 1, a vertex index out of range, or a coordinate that is not finite or beyond 2^1000 in
// magnitude (every sum, difference and area of the builders then stays finite).
BuildPrimitives buildPrimitives(const TriangleMesh& mesh, const std::string& builder);

// Primitives that are boxes alone, each centred on its box's centre.
BuildPrimitives boxPrimitives(std::vector<Aabb<double>> boxes);

// What every builder's primitive entry point checks. Throws std::invalid_argument naming `builder`
// for no primitive, more than 2^32 - 1, boxes and centres of different counts, an empty box, or a
// bound or centre that is not finite or beyond 2^1000 in magnitude.
void checkPrimitives(const BuildPrimitives& primitives, const std::string& builder);

// The first axis of greatest extent: x, then y, then z.
int widestAxis(const Aabb<double>& box);

}  // namespace rtu
