#pragma once
// Embree 3 (Debian's libembree-dev) as the reference users compare BVH builds and traversal
// with: its BVH builder (rtcBuildBVH) run into a tree of our own, so its SAH is summed exactly as
// ours is, and its single-ray traversal (rtcIntersect1) on a scene of the same float32 triangles.
// Single-threaded, as the golden models are.

#include <optional>
#include <vector>

#include <embree3/rtcore.h>

#include "geometry/ray.h"
#include "geometry/triangle_mesh.h"

namespace rtu {

class EmbreeReference {
 public:
  EmbreeReference();
  ~EmbreeReference();
  EmbreeReference(const EmbreeReference&) = delete;
  EmbreeReference& operator=(const EmbreeReference&) = delete;

  // The SAH (unit costs, normalised by the root's area, as measureQuality) of the binary BVH
  // Embree's builder makes at `quality` with leaves of 1-8 triangles; the build's seconds.
  struct Build {
    double sah = 0;
    double seconds = 0;
  };
  Build build(const TriangleMesh& mesh, RTCBuildQuality quality) const;

  // A scene of the mesh (float32 vertices, medium quality) to trace with rtcIntersect1.
  void setScene(const TriangleMesh& mesh);
  // The nearest hit's triangle, if any, with t in [0, inf).
  std::optional<unsigned> intersect(const Ray& ray) const;

 private:
  RTCDevice device_;
  RTCScene scene_ = nullptr;
};

}  // namespace rtu
