#pragma once
// The rays a renderer traces after its primary rays (issue 32), as world-space ray records: shadow
// rays toward point or area lights (inputs/light.h), ambient-occlusion rays, mirror reflections and
// diffuse bounces spawned from primary hits, and uniformly random rays in a model's box.
// docs/workloads.md describes them.
//
// Self-intersection on the SVO: a hit lies on a face of the hit voxel, and every ray spawned into
// the hemisphere of that face's normal leaves the voxel there, so the voxel's exit is the hit
// point. The ray starts `selfOffset` beyond it along the normal (the golden hit's t is within a
// few steps of the format) and is traced with a span (rtu/ray_span.h) that skips everything
// ending before its origin, the hit voxel included.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "inputs/light.h"
#include "kinds/svo/fixed_point.h"
#include "kinds/svo/thesis_records.h"
#include "rtu/model_header.h"
#include "rtu/ray_record.h"

namespace rtu {

enum class RayType { Primary, Shadow, Ao, Reflection, Diffuse, Random };

// "primary" ... "random"; throws std::invalid_argument naming the choices.
RayType parseRayType(const std::string& text);
const char* toString(RayType type);

// A primary ray's hit, world space.
struct SurfaceHit {
  uint32_t pixel = 0;
  glm::dvec3 point{0.0};     // on the hit voxel's face
  glm::dvec3 normal{0.0};    // unit, the face's, toward the ray that hit it
  glm::dvec3 incoming{0.0};  // unit direction of that ray
};

// The hits among `results` (the golden model's, in the order of `primaries`, rays of unit
// direction) ahead of their origins, on the model whose header is `header`.
std::vector<SurfaceHit> surfaceHits(const std::vector<RayRecord>& primaries,
                                    const std::vector<TraversalResult>& results,
                                    const ModelHeader& header, const FixedFormat& format);

struct SecondarySettings {
  RayType type = RayType::Shadow;
  // shadow: the lights, world space; the default, a point, lies along the shaded image's light
  // direction (app/frame_images.cpp), five units out
  std::vector<Light> lights{Light::point({2.25, 4.0, -2.0})};
  int lightSamples = 1;      // shadow: rays per hit to each area light (a point light takes 1)
  int samples = 1;           // ao and diffuse: rays per hit
  double aoDistance = 0.25;  // ao: the rays' length, world units
  // Off the surface along the normal, world units (0: none, where the kind's span starts past
  // the surface, as the BVH's float epsilon does).
  double selfOffset = 0x1p-12;
  // Seed 004's offset for a fixed-point grid (S4 §2.1.5): each coordinate moved 2 grid units
  // toward the side of the surface the ray leaves on, O[k] = h[k] + ((n . w > 0) ^ (n[k] < 0) ?
  // 2 : -2); every spawned ray leaves on the normal's side, so by 2 grid units along the sign of
  // n[k]. World units of 2 grid units (2 / SceneGrid::scale()); 0: none.
  double gridOffset = 0;
  uint64_t seed = 1;

  // Throws std::invalid_argument naming the setting: no light, samples or light samples outside 1
  // to 1024, a distance not positive and finite, an offset negative or not finite.
  void validate() const;
  // The ids a hit's rays take: pixel * raysPerHit() + k, k a sample, or for shadow rays a light's
  // sample, light by light (a point light one, an area light lightSamples).
  uint32_t raysPerHit() const;
};

// Where a spawned ray starts: `hit`'s point moved off its surface by `settings`' offsets.
glm::dvec3 spawnOrigin(const SurfaceHit& hit, const SecondarySettings& settings);

// The secondary rays of `hits` (type Shadow, Ao, Reflection or Diffuse), hit by hit in the order
// given, then light by light (each light's samples in turn) or sample by sample. A shadow ray runs
// from the spawn point to the light, or to a point of an area light drawn by the hit's sampler
// (any-hit, t in [0, 1]), and is left out when that point lies behind the face (the point is in
// its own shadow); an AO ray is any-hit over aoDistance; reflections and diffuse bounces have
// unit directions and take the nearest hit ahead. Throws std::invalid_argument for an id beyond
// 28 bits.
std::vector<RayRecord> spawnSecondaryRays(const std::vector<SurfaceHit>& hits,
                                          const SecondarySettings& settings, uint32_t modelAddress);

// `count` rays with origins uniform in the model's box (its cube placed by `header`) and uniform
// directions, each taking the nearest hit ahead of its origin; ids 0 to count - 1.
std::vector<RayRecord> randomRays(size_t count, const ModelHeader& header, uint64_t seed,
                                  uint32_t modelAddress);

}  // namespace rtu
