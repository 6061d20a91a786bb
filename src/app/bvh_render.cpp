#include "app/bvh_render.h"

#include <algorithm>
#include <cstdio>

#include <glm/geometric.hpp>

namespace rtu {

RenderedFrame bvhFrame(const Camera& camera, const FrameScene& scene,
                       const std::vector<BvhResult>& results) {
  RenderedFrame frame(camera);
  for (const BvhResult& result : results) {
    FramePixel pixel{result.hit, result.t, result.cost, glm::dvec3(0.0)};
    if (result.hit) {
      const auto& corners = scene.mesh.triangles.at(result.primitive);
      const glm::dvec3 a = scene.mesh.vertices[corners[0]], b = scene.mesh.vertices[corners[1]],
                       c = scene.mesh.vertices[corners[2]];
      // A normal maps to the world by R S^-1 (the inverse transpose of R S).
      pixel.normal = scene.placement.rotation * (glm::cross(b - a, c - a) / scene.placement.scale);
    }
    frame.place(result.idWord, pixel);
  }
  return frame;
}

std::string describeBvhResults(const std::vector<BvhResult>& results) {
  BvhCounters counters;
  uint64_t hits = 0, cost = 0;
  uint32_t maxCost = 0;
  for (const BvhResult& result : results) {
    hits += result.hit;
    cost += result.cost;
    maxCost = std::max(maxCost, result.cost);
    counters.add(result.counts);
  }
  const double rays = results.empty() ? 1.0 : static_cast<double>(results.size());
  char text[512];
  std::snprintf(text, sizeof text,
                "rays        %zu\n"
                "hits        %llu (%.1f %%)\n"
                "cost        mean %.2f, max %u cycles per ray (ROOT0 to last state before OUT)\n"
                "bvh         %.2f nodes, %.2f box tests, %.2f triangle tests, %.1f bytes per "
                "ray; %llu rays lost stack entries\n",
                results.size(), static_cast<unsigned long long>(hits), 100.0 * hits / rays,
                cost / rays, maxCost, counters.bvhNodesVisited / rays, counters.bvhBoxTests / rays,
                counters.bvhTriangleTests / rays, counters.bvhBytesFetched / rays,
                static_cast<unsigned long long>(counters.bvhStackOverflows));
  return text;
}

}  // namespace rtu
