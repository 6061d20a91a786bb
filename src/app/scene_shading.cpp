#include "app/scene_shading.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "kinds/core_result.h"

namespace rtu {

namespace {

const glm::dvec3 kSun = glm::normalize(glm::dvec3(0.5, 0.9, -0.35));

// The hit face's normal in the world, facing the ray. The result names the face's axis in the
// model's space (mirroring flips only its sign); normals go through the inverse transpose of
// R S, which is R S^-1.
glm::dvec3 worldNormal(const SceneHit& hit, const ModelPlacement& placement,
                       const glm::dvec3& direction) {
  const auto& normal = svoResult(hit.result).normal;  // the scene's models are SVO images
  glm::dvec3 axis(0.0);
  axis[normal[0] ? 0 : normal[1] ? 1 : 2] = 1.0;
  glm::dvec3 world = glm::normalize(placement.rotation * (axis / placement.scale));
  return glm::dot(world, direction) > 0.0 ? -world : world;
}

}  // namespace

glm::dvec3 sceneSky(const glm::dvec3& direction) {
  const double up = std::clamp(0.5 + 0.5 * direction.y, 0.0, 1.0);
  return glm::mix(glm::dvec3(0.55, 0.60, 0.68), glm::dvec3(0.20, 0.33, 0.55), up);
}

glm::dvec3 shadeSceneSurface(const glm::dvec3& colour, const glm::dvec3& normal) {
  const double sun = std::max(0.0, glm::dot(normal, kSun));
  const double skyLight = 0.5 + 0.5 * normal.y;
  return colour * (0.35 + 0.2 * skyLight + 0.6 * sun);
}

std::vector<float> shadeSceneFrame(const SceneFrame& frame, const SceneDescription& scene) {
  const Camera& camera = frame.camera;
  std::vector<float> rgb(frame.pixels.size() * 3);
  for (size_t i = 0; i < frame.pixels.size(); ++i) {
    const int x = static_cast<int>(i % static_cast<size_t>(camera.width));
    const int y = static_cast<int>(i / static_cast<size_t>(camera.width));
    const glm::dvec3 direction = camera.primaryRay(x, y).direction;
    const SceneHit& hit = frame.pixels[i];
    glm::dvec3 colour = sceneSky(direction);
    if (hit.instance >= 0) {
      const auto instance = static_cast<size_t>(hit.instance);
      colour = shadeSceneSurface(scene.instances[instance].colour,
                                 worldNormal(hit, frame.placements[instance], direction));
    }
    for (int c = 0; c < 3; ++c)
      rgb[i * 3 + static_cast<size_t>(c)] = static_cast<float>(std::clamp(colour[c], 0.0, 1.0));
  }
  return rgb;
}

}  // namespace rtu
