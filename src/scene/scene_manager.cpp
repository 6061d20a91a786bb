#include "scene/scene_manager.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

namespace rtu {

namespace {

glm::dvec3 toVector(const std::array<float, 3>& v) { return glm::dvec3(v[0], v[1], v[2]); }

// How far before a sphere's exact entry a hit inside it may still come out: the job's float32
// t-values and their conversion to fixed point round, by a few ulps of t and one step.
double roundingAllowance(double near) { return 1e-4 * (1.0 + std::abs(near)); }

}  // namespace

SphereSpan raySphereSpan(const RayRecord& ray, const BoundingSphere& sphere) {
  const glm::dvec3 direction = toVector(ray.direction);
  const glm::dvec3 toOrigin = toVector(ray.origin) - sphere.centre;
  // |o + t d - c|^2 = r^2:  a t^2 + 2 b t + c = 0.
  const double a = glm::dot(direction, direction);
  const double b = glm::dot(toOrigin, direction);
  const double c = glm::dot(toOrigin, toOrigin) - sphere.radius * sphere.radius;
  const double discriminant = b * b - a * c;
  if (discriminant < 0.0) return {};
  const double root = std::sqrt(discriminant);
  const SphereSpan span{true, (-b - root) / a, (-b + root) / a};
  if (span.far < 0.0) return {};
  return span;
}

std::vector<SceneCandidate> sceneCandidates(const RayRecord& ray,
                                            const std::vector<SceneInstance>& instances,
                                            SceneManagerOptions options, uint32_t& culled) {
  std::vector<SceneCandidate> candidates;
  for (uint32_t i = 0; i < instances.size(); ++i) {
    const SphereSpan span = raySphereSpan(ray, instances[i].sphere);
    if (span.crosses || !options.cull)
      candidates.push_back({span.crosses ? span.near : -INFINITY, i});
    else
      ++culled;
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const SceneCandidate& x, const SceneCandidate& y) {
              return x.near != y.near ? x.near < y.near : x.instance < y.instance;
            });
  return candidates;
}

bool hitEndsRayBefore(double tHit, double near) { return tHit < near - roundingAllowance(near); }

bool nearerSceneHit(const CoreKindResult& result, uint32_t instance, const CoreKindResult& best,
                    int bestInstance) {
  if (!hitAhead(result)) return false;
  if (bestInstance < 0 || nearer(result, best)) return true;
  return !nearer(best, result) && instance < static_cast<uint32_t>(bestInstance);
}

SceneManager::SceneManager(WordMemory memory, const GoldenConfig& golden,
                           std::vector<SceneInstance> instances, SceneManagerOptions options,
                           float epsilon)
    : model_(memory, golden),
      instances_(std::move(instances)),
      options_(options),
      epsilon_(epsilon) {
  CoreKinds::configOf<SvoKind>(coreConfigs_) = golden;
  headers_.reserve(instances_.size());
  for (const SceneInstance& instance : instances_)
    headers_.push_back(readModelHeader(memory, instance.headerAddress));
}

SceneHit SceneManager::trace(const RayRecord& ray, std::vector<IssuedJob>* issued) {
  // The golden model traverses: the SVO kind's miss until a hit.
  SceneHit best;
  best.result = kindMiss<SvoKind>(ray.id);
  uint32_t cost = 0;
  const std::vector<SceneCandidate> candidates =
      sceneCandidates(ray, instances_, options_, best.culled);
  for (size_t next = 0; next < candidates.size(); ++next) {
    const SceneCandidate& candidate = candidates[next];
    if (options_.earlyTermination && best.instance >= 0 &&
        hitEndsRayBefore(hitDistance(best.result, coreConfigs_), candidate.near)) {
      best.skipped = static_cast<uint32_t>(candidates.size() - next);
      break;
    }
    const CoreKindResult result =
        model_.trace(rayRecordToJob(ray, headers_[candidate.instance], epsilon_));
    ++best.jobs;
    cost += resultCost(result);
    if (issued) issued->push_back({candidate.instance, resultCost(result), ray.id});
    if (nearerSceneHit(result, candidate.instance, best.result, best.instance)) {
      best.result = result;
      best.instance = static_cast<int>(candidate.instance);
    }
  }
  setResultCost(best.result, cost);
  return best;
}

}  // namespace rtu
