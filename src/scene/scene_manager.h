#pragma once
// The scene manager of thesis section 4.3.4 and chapter 8, untimed: one world-space ray against
// several instances of animated models, each a model header in SVO memory (model_header.h).
//
// For each ray it intersects the instances' bounding spheres, culls those the ray misses (or that
// lie wholly behind its origin), and issues one job per remaining instance in front-to-back order
// of the spheres' entry distances. Each job goes through the job manager's set-up
// (rayRecordToJob: the ray moves into the model, the model stays put) and the golden traversal.
// The nearest hit is kept; issuing stops as soon as the nearest hit so far lies before the next
// sphere's entry, since no voxel of that instance, or of any after it, can be nearer ("before"
// with an allowance of 1e-4 (1 + |entry|) for the rounding of the job's t-values).
//
// Hits behind the ray origin (t < 0, reported when the origin lies inside a model's cube) are no
// hits: the camera sees only what is in front of it. Equal t: the lower instance index wins, so
// the answer does not depend on the order jobs were issued in.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "kinds/core_result.h"
#include "kinds/svo/golden_model.h"
#include "kinds/svo/ray_transform.h"
#include "rtu/word_memory.h"

namespace rtu {

struct BoundingSphere {
  glm::dvec3 centre{0.0};
  double radius = 0.0;
};

// Where a ray (origin + t direction, any non-zero length) is inside a sphere: [near, far].
struct SphereSpan {
  bool crosses = false;  // false: the ray's line misses the sphere, or the sphere is behind it
  double near = 0.0;
  double far = 0.0;
};
SphereSpan raySphereSpan(const RayRecord& ray, const BoundingSphere& sphere);

struct SceneInstance {
  uint32_t headerAddress = 0;
  BoundingSphere sphere;  // holding every solid voxel of the instance, in world space
};

struct SceneManagerOptions {
  bool cull = true;              // false: every instance is traced, sphere or not
  bool earlyTermination = true;  // false: every instance not culled is traced
};

// What the manager decides per ray, shared by this untimed manager and the cycle-accurate one
// (src/scene/scene_manager.h).
struct SceneCandidate {
  double near;  // the sphere's entry distance (-infinity when not culling and the ray misses it)
  uint32_t instance;
};
// The instances `ray` is traced against, in issue order; adds those culled to `culled`.
std::vector<SceneCandidate> sceneCandidates(const RayRecord& ray,
                                            const std::vector<SceneInstance>& instances,
                                            SceneManagerOptions options, uint32_t& culled);
// Whether a hit at `tHit` (world units) ends the ray before a candidate whose sphere begins at
// `near`.
bool hitEndsRayBefore(double tHit, double near);
// Whether `result` of `instance` is nearer than `best` of `bestInstance` (-1: no hit so far), both
// results of the same kind: a hit ahead of the ray's origin (hitAhead) and nearer than the best
// (nearer), on equal distances of the lower instance.
bool nearerSceneHit(const CoreKindResult& result, uint32_t instance, const CoreKindResult& best,
                    int bestInstance);

// One job the manager issued, for a timing model of the frame.
struct IssuedJob {
  uint32_t instance = 0;
  uint32_t cost = 0;
  uint32_t ray = 0;  // the ray's id
};

struct SceneHit {
  // The nearest hit's result (its id word carries the ray id and that job's a bits), or a miss
  // with the ray id. Either way `cost` is the sum over every job issued for the ray.
  CoreKindResult result;
  int instance = -1;  // the instance hit, -1 on a miss
  uint32_t jobs = 0;
  uint32_t culled = 0;   // instances whose sphere the ray misses
  uint32_t skipped = 0;  // instances not traced because a nearer hit ended the ray
};

class SceneManager {
 public:
  // Reads every instance's header once, as the job manager does once per frame. Throws
  // std::runtime_error naming the address of an invalid header.
  SceneManager(WordMemory memory, const GoldenConfig& golden, std::vector<SceneInstance> instances,
               SceneManagerOptions options = {}, float epsilon = kDefaultDirectionEpsilonF);

  // `ray.modelAddress` is ignored: the manager names each instance's header itself. Appends the
  // jobs it issues to `issued` when given.
  SceneHit trace(const RayRecord& ray, std::vector<IssuedJob>* issued = nullptr);

  const std::vector<SceneInstance>& instances() const { return instances_; }

  static constexpr float kDefaultDirectionEpsilonF = static_cast<float>(kDefaultDirectionEpsilon);

 private:
  GoldenModel model_;
  CoreKindConfigs coreConfigs_;  // the golden model's settings, for the hits' distances
  std::vector<SceneInstance> instances_;
  std::vector<ModelHeader> headers_;
  SceneManagerOptions options_;
  float epsilon_;
};

}  // namespace rtu
