#include "explore/reference_frame.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "geometry/triangle_tests.h"
#include "kinds/bvh/sah_builder.h"

namespace rtu {
namespace {

// Wider than the box by far more than double rounding moves a hit: a relative 1e-9 of the box's
// size and position.
Aabb<double> widened(const Aabb<double>& box) {
  const glm::dvec3 margin =
      1e-9 * (glm::abs(box.lower) + glm::abs(box.upper) + box.extent()) + glm::dvec3(1e-300);
  return Aabb<double>{box.lower - margin, box.upper + margin};
}

// Whether the ray meets `box` within [0, limit] (limit included).
bool meetsBox(const Ray& ray, const glm::dvec3& inverse, const Aabb<double>& box, double limit) {
  double near = 0, far = limit;
  for (int axis = 0; axis < 3; ++axis) {
    if (ray.direction[axis] == 0) {
      if (ray.origin[axis] < box.lower[axis] || ray.origin[axis] > box.upper[axis]) return false;
      continue;
    }
    double t0 = (box.lower[axis] - ray.origin[axis]) * inverse[axis];
    double t1 = (box.upper[axis] - ray.origin[axis]) * inverse[axis];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1 * (1 + 1e-12));
  }
  return near <= far;
}

}  // namespace

ReferenceTracer::ReferenceTracer(TriangleMesh mesh) : mesh_(std::move(mesh)) {
  if (mesh_.triangles.empty())
    throw std::invalid_argument("the float64 reference needs at least one triangle");
  tree_ = buildSah(mesh_).tree;
  for (const BuildNode& node : tree_.nodes) boxes_.push_back(widened(node.box));
}

// Pass 1 finds every triangle hit within a relative 1e-9 of the nearest, through the BVH; pass 2
// runs closestHit's rule over them in index order, so that ties and the watertight test's limit
// (checked before its division) resolve as they do over every triangle.
std::optional<OracleHit> ReferenceTracer::trace(const Ray& ray) const {
  const ShearedRay<double> sheared(ray.origin, ray.direction);
  const glm::dvec3 inverse = 1.0 / ray.direction;
  const auto slack = [](double t) { return t * (1 + 1e-9) + 1e-300; };
  double nearest = INFINITY;
  std::vector<std::pair<uint32_t, double>> candidates;
  std::vector<uint32_t> pending{0};
  while (!pending.empty()) {
    const uint32_t index = pending.back();
    pending.pop_back();
    if (!meetsBox(ray, inverse, boxes_[index], slack(nearest))) continue;
    const BuildNode& node = tree_.nodes[index];
    if (!node.leaf()) {
      pending.push_back(node.right);
      pending.push_back(node.left);
      continue;
    }
    for (uint32_t k = node.first; k < node.first + node.count; ++k) {
      const uint32_t i = tree_.refs[k];
      const auto& c = mesh_.triangles[i];
      const auto hit = watertight(sheared, mesh_.vertices[c[0]], mesh_.vertices[c[1]],
                                  mesh_.vertices[c[2]], 0.0, slack(nearest));
      if (!hit) continue;
      candidates.emplace_back(i, hit->t);
      nearest = std::min(nearest, hit->t);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::optional<OracleHit> best;
  for (const auto& [i, t] : candidates) {
    if (t > slack(nearest)) continue;
    const auto& c = mesh_.triangles[i];
    const auto hit = watertight(sheared, mesh_.vertices[c[0]], mesh_.vertices[c[1]],
                                mesh_.vertices[c[2]], 0.0, best ? best->t : INFINITY);
    if (hit && (!best || hit->t < best->t)) best = OracleHit{hit->t, hit->u, hit->v, i};
  }
  return best;
}

TriangleMesh placedMesh(const TriangleMesh& mesh, const ModelPlacement& placement) {
  TriangleMesh placed = mesh;
  for (glm::dvec3& v : placed.vertices)
    v = placement.translation + placement.rotation * (placement.scale * v);
  return placed;
}

std::vector<std::optional<OracleHit>> referenceFrame(const ReferenceTracer& tracer,
                                                     const Camera& camera) {
  std::vector<std::optional<OracleHit>> hits;
  for (Ray ray : frameRays(camera)) {
    ray.direction = glm::normalize(ray.direction);
    hits.push_back(tracer.trace(ray));
  }
  return hits;
}

}  // namespace rtu
