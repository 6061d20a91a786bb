#include "app/triangle_render.h"

#include <cstdio>

#include <glm/geometric.hpp>

#include "kinds/bih/bih_counters.h"
#include "kinds/bvh/bvh_counters.h"
#include "kinds/kd/kd_counters.h"

namespace rtu {
namespace {

double perRay(uint64_t count, size_t rays) {
  return static_cast<double>(count) / static_cast<double>(std::max<size_t>(rays, 1));
}

}  // namespace

FramePixel trianglePixel(const FrameScene& scene, bool hit, double distance, uint32_t cost,
                         uint32_t primitive) {
  FramePixel pixel{hit, distance, cost, glm::dvec3(0.0)};
  if (!hit) return pixel;
  pixel.triangle = primitive;
  const auto& corners = scene.mesh.triangles.at(primitive);
  const glm::dvec3 a = scene.mesh.vertices[corners[0]], b = scene.mesh.vertices[corners[1]],
                   c = scene.mesh.vertices[corners[2]];
  // A normal maps to the world by R S^-1 (the inverse transpose of R S).
  pixel.normal = scene.placement.rotation * (glm::cross(b - a, c - a) / scene.placement.scale);
  return pixel;
}

std::string describeHits(size_t rays, uint64_t hits, uint64_t cost, uint32_t maxCost) {
  char text[256];
  std::snprintf(text, sizeof text,
                "rays        %zu\n"
                "hits        %llu (%.1f %%)\n"
                "cost        mean %.2f, max %u cycles per ray (first state to last before OUT)\n",
                rays, static_cast<unsigned long long>(hits), 100.0 * perRay(hits, rays),
                perRay(cost, rays), maxCost);
  return text;
}

// The "rays", "hits" and "cost" lines of a tally.
template <class Counters>
std::string describeTriangleHits(const TriangleTally<Counters>& tally) {
  return describeHits(tally.rays, tally.hits, tally.cost, tally.maxCost);
}

std::string describeBvhResults(const TriangleTally<BvhCounters>& tally) {
  const BvhCounters& counters = tally.counters;
  const size_t rays = tally.rays;
  char text[256];
  std::snprintf(text, sizeof text,
                "bvh         %.2f nodes, %.2f box tests, %.2f triangle tests, %.1f bytes per "
                "ray; %llu rays lost stack entries\n",
                perRay(counters.bvhNodesVisited, rays), perRay(counters.bvhBoxTests, rays),
                perRay(counters.bvhTriangleTests, rays), perRay(counters.bvhBytesFetched, rays),
                static_cast<unsigned long long>(counters.bvhStackOverflows));
  return describeTriangleHits(tally) + text;
}

std::string describeBihResults(const TriangleTally<BihCounters>& tally, uint32_t unitInterval) {
  const BihCounters& counters = tally.counters;
  const size_t rays = tally.rays;
  const uint64_t cycles = tally.cost;
  char text[512];
  std::snprintf(text, sizeof text,
                "bih         %.2f nodes, %.2f triangle tests, %.1f bytes per ray; %llu rays lost "
                "stack entries, %llu divider errors\n"
                "unit fill   %.1f %% (triangle tests x interval over the rays' cycles: seed 004 "
                "measured about 40 %%)\n",
                perRay(counters.bihNodesVisited, rays), perRay(counters.bihTriangleTests, rays),
                perRay(counters.bihBytesFetched, rays),
                static_cast<unsigned long long>(counters.bihStackOverflows),
                static_cast<unsigned long long>(counters.bihDividerErrors),
                100.0 * perRay(counters.bihTriangleTests * unitInterval, cycles));
  return describeTriangleHits(tally) + text;
}

std::string describeKdResults(const TriangleTally<KdCounters>& tally) {
  const KdCounters& counters = tally.counters;
  const size_t rays = tally.rays;
  char text[256];
  std::snprintf(text, sizeof text,
                "kd          %.2f nodes, %.2f triangle tests, %.3f restarts, %.3f short-stack "
                "drops, %.1f bytes per ray\n",
                perRay(counters.kdNodesVisited, rays), perRay(counters.kdTriangleTests, rays),
                perRay(counters.kdRestarts, rays), perRay(counters.kdShortStackDrops, rays),
                perRay(counters.kdBytesFetched, rays));
  return describeTriangleHits(tally) + text;
}

}  // namespace rtu
