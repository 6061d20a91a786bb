#pragma once
// The golden traversal of a two-level BVH (two_level.h) for one world-space ray: the top level's
// walk (top_level_walk.h) in world space hands out instances; at each, the world ray moves into
// the instance's mesh space by the shared float32 transform (`toModelSpace`,
// rtu/model_transform.h: t keeps the world ray's units, the direction is not renormalised) and the
// mesh's image is traced by the mesh golden traversal (BvhKind under GoldenShell) with t_max = the
// nearest hit so far. A mesh hit replaces the best only when strictly nearer, so of equal t the
// first found wins. The two levels are kept apart (docs/triangles.md, "Two-level BVH"): the mesh
// traversal is the core's job as it stands, so the timed issue can run it on a core and the walk
// in the scene manager or as a state machine of its own.

#include <cstdint>
#include <vector>

#include "kinds/bvh/bvh_kind.h"
#include "kinds/bvh/top_level_walk.h"
#include "kinds/bvh/two_level.h"
#include "rtu/golden_shell.h"
#include "rtu/model_transform.h"
#include "rtu/ray_record.h"

namespace rtu {

// What one ray counted: the top level's walk, and the mesh traversals' counts and costs summed.
struct TwoLevelCounts {
  TopLevelCounts top;
  BvhRayCounts mesh;
  uint64_t meshCost = 0;  // states of every mesh traversal
};

struct TwoLevelResult {
  bool hit = false;
  float t = 0, u = 0, v = 0;  // t along the world ray's direction; u, v as BvhResult
  uint32_t instance = 0;      // the hit instance's index in the frame's top level
  uint32_t primitive = 0;     // the hit triangle's source id in its mesh
  TwoLevelCounts counts;
};

template <class Intersector>
class TwoLevelTraversal {
 public:
  using MeshKind = BvhKind<Intersector>;

  // `bvh` must outlive the traversal; its top level may be re-placed between rays.
  explicit TwoLevelTraversal(const TwoLevelBvh& bvh, const BvhConfig& config = {})
      : bvh_(bvh), walk_(config.stackDepth) {
    for (const MeshBvh& mesh : bvh.meshes()) shells_.emplace_back(mesh.image.memory(), config);
  }

  // The nearest hit of `ray` (world space; its model address is not used) with t in [tMin, tMax].
  TwoLevelResult trace(const RayRecord& ray, float tMin, float tMax) {
    const TopLevel& top = bvh_.topLevel();
    TwoLevelResult result;
    float tBest = tMax;
    walk_.start(top.image, makeBvhRay(toVec(ray.origin), toVec(ray.direction), tMin, tMax));
    while (const auto instance = walk_.next(tBest)) {
      const uint32_t mesh = top.instances[*instance].mesh;
      const ModelSpaceRay model = toModelSpace(ray, top.transforms[*instance]);
      const BvhJob job{makeBvhRay(toVec(model.origin), toVec(model.direction), tMin, tBest),
                       bvh_.meshes()[mesh].sections};
      BvhResult found;
      shells_[mesh].run(0, job, found);
      add(found, result.counts);
      if (found.hit && (!result.hit || found.t < tBest)) {
        tBest = found.t;
        keep(found, *instance, result);
      }
    }
    result.counts.top = walk_.counts();
    return result;
  }

 private:
  static Vec3<float> toVec(const std::array<float, 3>& a) { return Vec3<float>(a[0], a[1], a[2]); }

  static void add(const BvhResult& found, TwoLevelCounts& counts) {
    counts.mesh.nodes += found.counts.nodes;
    counts.mesh.boxTests += found.counts.boxTests;
    counts.mesh.triangleTests += found.counts.triangleTests;
    counts.mesh.pushes += found.counts.pushes;
    counts.mesh.pops += found.counts.pops;
    counts.mesh.dropped += found.counts.dropped;
    counts.meshCost += found.cost;
  }

  static void keep(const BvhResult& found, uint32_t instance, TwoLevelResult& result) {
    result.hit = true;
    result.t = found.t;
    result.u = found.u;
    result.v = found.v;
    result.instance = instance;
    result.primitive = found.primitive;
  }

  const TwoLevelBvh& bvh_;
  TopLevelWalk walk_;
  std::vector<GoldenShell<MeshKind>> shells_;  // one per mesh, over its image
};

}  // namespace rtu
