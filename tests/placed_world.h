#pragma once
// A two-level scene as the float64 oracle sees it (geometry/triangle_oracle.h): every instance's
// float32 mesh vertices (what its mesh image holds) placed into the world in double by the exact
// placement, p = R (S v) + T, the instances' triangles concatenated in order, as a two-level hit
// names them (kinds/bvh/two_level_image.h); and the tests' four overlapping instances of a mesh.

#include <cstdint>
#include <vector>

#include "geometry/triangle_mesh.h"
#include "kinds/bvh/two_level.h"
#include "rtu/model_transform.h"

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

// Four overlapping instances of mesh 0 around its box (moved by `shift` along x): one as it is,
// one turned, one scaled by half and turned about two axes, one scaled unevenly.
inline std::vector<BvhInstance> overlappingInstances(const Aabb<double>& box, double shift) {
  const glm::dvec3 e = box.extent();
  const auto at = [&](glm::dvec3 offset, glm::dvec3 degrees, glm::dvec3 scale) {
    return BvhInstance{0, ModelPlacement{offset * e + glm::dvec3(shift, 0, 0),
                                         rotationFromEulerDegrees(degrees), scale}};
  };
  return {at({0, 0, 0}, {0, 0, 0}, glm::dvec3(1)), at({0.6, 0, 0.1}, {0, 30, 0}, glm::dvec3(1)),
          at({0.1, 0.2, 0.5}, {20, 0, 45}, glm::dvec3(0.5)),
          at({-0.5, 0.3, 0}, {0, -60, 10}, {1.5, 0.75, 1.25})};
}

}  // namespace rtu
