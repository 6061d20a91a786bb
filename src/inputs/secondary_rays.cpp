#include "inputs/secondary_rays.h"

#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "inputs/ray_sampler.h"

namespace rtu {

namespace {

const char* const kRayTypeNames[] = {"primary", "shadow", "ao", "reflection", "diffuse", "random"};

// Row k of R^T is column k of R: model axis k in the world.
glm::dvec3 worldAxis(const ModelTransform& transform, int k) {
  const auto& m = transform.inverseRotation;
  return {m[3 * k], m[3 * k + 1], m[3 * k + 2]};
}

// p_world = R (S p_model) + T.
glm::dvec3 modelToWorld(const ModelTransform& transform, const glm::dvec3& p) {
  glm::dvec3 world{transform.translation[0], transform.translation[1], transform.translation[2]};
  for (int k = 0; k < 3; ++k) world += worldAxis(transform, k) * (p[k] / transform.inverseScale[k]);
  return world;
}

int normalAxis(const TraversalResult& result) {
  for (int k = 0; k < 3; ++k)
    if (result.normal[k] != 0) return k;
  throw std::logic_error("a hit without a normal");
}

RayRecord record(uint64_t id, const glm::dvec3& origin, const glm::dvec3& direction, RaySpan span,
                 uint32_t modelAddress) {
  if (id > kMaxRayId)
    throw std::invalid_argument("secondary ray id " + std::to_string(id) +
                                " does not fit 28 bits: fewer pixels or samples");
  RayRecord ray;
  ray.id = static_cast<uint32_t>(id);
  ray.span = span;
  ray.modelAddress = modelAddress;
  for (int k = 0; k < 3; ++k) {
    ray.origin[k] = static_cast<float>(origin[k]);
    ray.direction[k] = static_cast<float>(direction[k]);
  }
  return ray;
}

void checkPositive(double value, const char* what) {
  if (!(value > 0.0 && std::isfinite(value)))
    throw std::invalid_argument(std::string(what) + " must be positive and finite, got " +
                                std::to_string(value));
}

void checkNotNegative(double value, const char* what) {
  if (!(value >= 0.0 && std::isfinite(value)))
    throw std::invalid_argument(std::string(what) + " must be 0 or positive and finite, got " +
                                std::to_string(value));
}

// The light each of a hit's shadow rays goes to, light by light (an area light's samples in turn).
std::vector<const Light*> shadowRayLights(const SecondarySettings& settings) {
  std::vector<const Light*> lights;
  if (settings.type != RayType::Shadow) return lights;
  for (const Light& light : settings.lights)
    lights.insert(lights.end(), light.isArea() ? settings.lightSamples : 1, &light);
  return lights;
}

}  // namespace

RayType parseRayType(const std::string& text) {
  for (int i = 0; i < 6; ++i)
    if (text == kRayTypeNames[i]) return static_cast<RayType>(i);
  throw std::invalid_argument("--ray-type " + text +
                              ": choose primary, shadow, ao, reflection, diffuse or random");
}

const char* toString(RayType type) { return kRayTypeNames[static_cast<int>(type)]; }

std::vector<SurfaceHit> surfaceHits(const std::vector<RayRecord>& primaries,
                                    const std::vector<TraversalResult>& results,
                                    const ModelHeader& header, const FixedFormat& format) {
  std::vector<SurfaceHit> hits;
  for (size_t i = 0; i < results.size(); ++i) {
    const TraversalResult& result = results[i];
    if (!result.hit || result.tHit < 0) continue;
    const RayRecord& ray = primaries[i];
    SurfaceHit hit;
    hit.pixel = ray.id;
    const glm::dvec3 origin{ray.origin[0], ray.origin[1], ray.origin[2]};
    hit.incoming = glm::normalize(glm::dvec3{ray.direction[0], ray.direction[1], ray.direction[2]});
    hit.point = origin + format.toDouble(result.tHit) * hit.incoming;
    hit.normal = glm::normalize(worldAxis(header, normalAxis(result)));
    if (glm::dot(hit.normal, hit.incoming) > 0.0) hit.normal = -hit.normal;
    hits.push_back(hit);
  }
  return hits;
}

void SecondarySettings::validate() const {
  if (type == RayType::Shadow && lights.empty())
    throw std::invalid_argument("--light: shadow rays need at least one light");
  if (samples < 1 || samples > 1024)
    throw std::invalid_argument("--samples must be 1 to 1024, got " + std::to_string(samples));
  if (lightSamples < 1 || lightSamples > 1024)
    throw std::invalid_argument("--light-samples must be 1 to 1024, got " +
                                std::to_string(lightSamples));
  checkPositive(aoDistance, "--ao-distance");
  checkNotNegative(selfOffset, "the self-intersection offset");
  checkNotNegative(gridOffset, "the grid offset");
}

glm::dvec3 spawnOrigin(const SurfaceHit& hit, const SecondarySettings& settings) {
  glm::dvec3 origin = hit.point + settings.selfOffset * hit.normal;
  for (int k = 0; k < 3; ++k)
    origin[k] += hit.normal[k] < 0 ? -settings.gridOffset : settings.gridOffset;
  return origin;
}

uint32_t SecondarySettings::raysPerHit() const {
  if (type == RayType::Shadow) {
    uint32_t rays = 0;
    for (const Light& light : lights) rays += light.isArea() ? lightSamples : 1;
    return rays;
  }
  if (type == RayType::Ao || type == RayType::Diffuse) return static_cast<uint32_t>(samples);
  return 1;
}

std::vector<RayRecord> spawnSecondaryRays(const std::vector<SurfaceHit>& hits,
                                          const SecondarySettings& settings,
                                          uint32_t modelAddress) {
  settings.validate();
  const uint64_t perHit = settings.raysPerHit();
  const std::vector<const Light*> lightOfRay = shadowRayLights(settings);
  std::vector<RayRecord> rays;
  rays.reserve(hits.size() * perHit);
  for (const SurfaceHit& hit : hits) {
    const glm::dvec3 origin = spawnOrigin(hit, settings);
    RaySampler sampler(settings.seed, hit.pixel);
    for (uint64_t k = 0; k < perHit; ++k) {
      const uint64_t id = hit.pixel * perHit + k;
      switch (settings.type) {
        case RayType::Shadow: {
          const glm::dvec3 toLight = lightOfRay[k]->sample(sampler) - origin;
          if (glm::dot(toLight, hit.normal) > 0.0)
            rays.push_back(record(id, origin, toLight, RaySpan::AnyHit, modelAddress));
          break;
        }
        case RayType::Ao:
          rays.push_back(record(id, origin,
                                settings.aoDistance * sampler.cosineHemisphere(hit.normal),
                                RaySpan::AnyHit, modelAddress));
          break;
        case RayType::Reflection:
          rays.push_back(record(id, origin, glm::reflect(hit.incoming, hit.normal), RaySpan::Ahead,
                                modelAddress));
          break;
        case RayType::Diffuse:
          rays.push_back(record(id, origin, sampler.cosineHemisphere(hit.normal), RaySpan::Ahead,
                                modelAddress));
          break;
        default: throw std::invalid_argument("spawnSecondaryRays: not a secondary ray type");
      }
    }
  }
  return rays;
}

std::vector<RayRecord> randomRays(size_t count, const ModelHeader& header, uint64_t seed,
                                  uint32_t modelAddress) {
  if (count > size_t{kMaxRayId} + 1)
    throw std::invalid_argument("--random-rays " + std::to_string(count) + ": ids have 28 bits");
  std::vector<RayRecord> rays;
  rays.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    RaySampler sampler(seed, i);
    glm::dvec3 model;
    for (int k = 0; k < 3; ++k) model[k] = 2.0 * sampler.uniform() - 1.0;
    rays.push_back(record(i, modelToWorld(header, model), sampler.uniformSphere(), RaySpan::Ahead,
                          modelAddress));
  }
  return rays;
}

}  // namespace rtu
