#pragma once
// A two-level scene as the float64 oracle sees it (geometry/triangle_oracle.h): every instance's
// float32 mesh vertices (what its mesh image holds) placed into the world in double by the exact
// placement, p = R (S v) + T, the instances' triangles concatenated in order, as a two-level hit
// names them (kinds/bvh/two_level_image.h).

#include <cstdint>
#include <vector>

#include "geometry/triangle_mesh.h"
#include "kinds/bvh/two_level.h"

namespace rtu {

inline TriangleMesh placedWorld(const std::vector<TriangleMesh>& meshes,
                                const std::vector<BvhInstance>& instances) {
  TriangleMesh world;
  for (const BvhInstance& instance : instances) {
    const auto offset = static_cast<uint32_t>(world.vertices.size());
    const ModelPlacement& p = instance.placement;
    for (const glm::dvec3& v : meshes[instance.mesh].vertices)
      world.vertices.push_back(p.rotation * (p.scale * glm::dvec3(glm::vec3(v))) + p.translation);
    for (const auto& t : meshes[instance.mesh].triangles)
      world.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  return world;
}

}  // namespace rtu
