#include "geometry/ray_sets.h"

#include <cmath>
#include <random>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace rtu {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Uniform in [0, 1): the top 53 bits of the generator's word.
double unit(std::mt19937_64& random) { return static_cast<double>(random() >> 11) * 0x1.0p-53; }

uint32_t below(std::mt19937_64& random, size_t bound) {
  return static_cast<uint32_t>(unit(random) * static_cast<double>(bound));
}

// Uniform on the unit sphere (Archimedes: z uniform, angle uniform).
glm::dvec3 direction(std::mt19937_64& random) {
  const double z = 2 * unit(random) - 1;
  const double angle = 2 * kPi * unit(random);
  const double r = std::sqrt(std::max(0.0, 1 - z * z));
  return {r * std::cos(angle), r * std::sin(angle), z};
}

double diagonal(const Aabb<double>& box) { return glm::length(box.extent()); }

void appendView(const Aabb<double>& box, double angle, int width, int height,
                std::vector<Ray>& rays) {
  const glm::dvec3 centre = box.centre();
  const double span = diagonal(box);
  const glm::dvec3 eye = centre + 1.5 * span * glm::dvec3(std::cos(angle), 0.35, std::sin(angle));
  const glm::dvec3 forward = glm::normalize(centre - eye);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
  const glm::dvec3 up = glm::cross(right, forward);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double s = (x + 0.5) / width - 0.5, t = 0.5 - (y + 0.5) / height;
      const glm::dvec3 target = centre + span * (s * right + t * up);
      rays.push_back(Ray{eye, glm::normalize(target - eye)});
    }
}

}  // namespace

Aabb<double> meshBounds(const TriangleMesh& mesh) {
  Aabb<double> box;
  for (const auto& triangle : mesh.triangles)
    for (uint32_t v : triangle) box.grow(mesh.vertices[v]);
  return box;
}

std::vector<Ray> viewRays(const Aabb<double>& box, int views, int width, int height) {
  if (box.empty()) throw std::invalid_argument("viewRays: the box is empty");
  std::vector<Ray> rays;
  rays.reserve(static_cast<size_t>(views) * width * height);
  for (int view = 0; view < views; ++view)
    appendView(box, 0.3 + 2 * kPi * view / views, width, height, rays);
  return rays;
}

std::vector<AimedRay> aimedFeatureRays(const TriangleMesh& mesh, size_t count, uint64_t seed) {
  if (mesh.triangles.empty()) throw std::invalid_argument("aimedRays: the mesh has no triangle");
  std::mt19937_64 random(seed);
  const double distance = diagonal(meshBounds(mesh));
  std::vector<AimedRay> rays;
  rays.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    const auto& triangle = mesh.triangles[below(random, mesh.triangles.size())];
    const uint32_t corner = below(random, 3);
    const uint32_t a = triangle[corner], b = triangle[(corner + 1) % 3];
    const bool vertex = i % 2 == 0;
    const glm::dvec3 target = vertex ? mesh.vertices[a]
                                     : (mesh.vertices[a] + mesh.vertices[b]) * 0.5;
    const glm::dvec3 d = direction(random);
    rays.push_back(AimedRay{Ray{target - distance * d, d}, a, vertex ? a : b});
  }
  return rays;
}

std::vector<Ray> aimedRays(const TriangleMesh& mesh, size_t count, uint64_t seed) {
  std::vector<Ray> rays;
  rays.reserve(count);
  for (const AimedRay& aimed : aimedFeatureRays(mesh, count, seed)) rays.push_back(aimed.ray);
  return rays;
}

std::vector<Ray> randomRays(const Aabb<double>& box, size_t count, uint64_t seed) {
  if (box.empty()) throw std::invalid_argument("randomRays: the box is empty");
  std::mt19937_64 random(seed);
  std::vector<Ray> rays;
  rays.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    glm::dvec3 origin;
    for (int k = 0; k < 3; ++k) origin[k] = box.lower[k] + unit(random) * box.extent()[k];
    rays.push_back(Ray{origin, direction(random)});
  }
  return rays;
}

}  // namespace rtu
