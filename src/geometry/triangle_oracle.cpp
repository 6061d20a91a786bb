#include "geometry/triangle_oracle.h"

#include "geometry/triangle_tests.h"

namespace rtu {

std::optional<OracleHit> closestHit(const TriangleMesh& mesh, const Ray& ray, double tMin,
                                    double tMax) {
  const ShearedRay<double> sheared(ray.origin, ray.direction);
  std::optional<OracleHit> best;
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& corners = mesh.triangles[i];
    // Later triangles must be strictly nearer: the lowest index wins a tie.
    const double limit = best ? best->t : tMax;
    const auto hit = watertight(sheared, mesh.vertices[corners[0]], mesh.vertices[corners[1]],
                                mesh.vertices[corners[2]], tMin, limit);
    if (hit && (!best || hit->t < best->t))
      best = OracleHit{hit->t, hit->u, hit->v, static_cast<uint32_t>(i)};
  }
  return best;
}

}  // namespace rtu
