#include "app/triangle_render.h"

#include <cstdio>

namespace rtu {

FramePixel trianglePixel(const FrameScene& scene, bool hit, double distance, uint32_t cost,
                         uint32_t primitive) {
  FramePixel pixel{hit, distance, cost, glm::dvec3(0.0)};
  if (!hit) return pixel;
  pixel.triangle = primitive;
  pixel.normal = triangleNormal(scene, primitive);
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

}  // namespace rtu
