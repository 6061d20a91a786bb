#pragma once
// The float64 reference `rtusim compare` measures every architecture's frame against (issue 30):
// each camera ray's nearest hit over the scene's triangles in the world, by the rule of the
// triangle kinds' oracle (geometry/triangle_oracle.h: the float64 watertight test, ties to the
// lowest triangle index). Testing every triangle for every ray, as closestHit does, takes hours on
// a mesh of 75,000 triangles at 1280x720, so the triangles are found through a BVH over them (the
// binned SAH build in double) whose boxes are only widened, never narrowed: it skips no triangle
// that could hold the nearest hit, and gives what closestHit gives
// (tests/test_reference_frame.cpp checks the two on the same rays).

#include <optional>
#include <vector>

#include "geometry/ray.h"
#include "geometry/triangle_mesh.h"
#include "geometry/triangle_oracle.h"
#include "inputs/camera.h"
#include "kinds/bvh/build_tree.h"
#include "rtu/model_transform.h"

namespace rtu {

class ReferenceTracer {
 public:
  // Throws std::invalid_argument for a mesh without triangles.
  explicit ReferenceTracer(TriangleMesh mesh);
  // closestHit(mesh, ray, 0, infinity).
  std::optional<OracleHit> trace(const Ray& ray) const;
  const TriangleMesh& mesh() const { return mesh_; }

 private:
  TriangleMesh mesh_;
  BuildTree tree_;
  std::vector<Aabb<double>> boxes_;  // each node's box, widened
};

// The mesh's vertices placed in the world (rotation, per-axis scale, translation).
TriangleMesh placedMesh(const TriangleMesh& mesh, const ModelPlacement& placement);

// Each pixel's reference hit (x + y * width), rays through the pixel centres with unit directions,
// so t is a distance in the world.
std::vector<std::optional<OracleHit>> referenceFrame(const ReferenceTracer& tracer,
                                                     const Camera& camera);

}  // namespace rtu
