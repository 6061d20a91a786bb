#include "raypipe/raypipe_golden.h"

#include <stdexcept>

#include "kinds/kd/kd_kind.h"
#include "rtu/golden_shell.h"

namespace rtu {

KdTraversalConfig kdTraversalConfig(const RaypipeConfig& config) {
  return KdTraversalConfig{config.shortStackDepth, config.division, config.tMaxClamp, {}};
}

void RaypipeFrameTotals::add(const RaypipePixel& pixel) {
  ++rays;
  boxMisses += pixel.boxMiss;
  hits += pixel.hit;
  nodes += pixel.counts.nodes;
  leaves += pixel.counts.leaves;
  triangleTests += pixel.counts.triangleTests;
  pushes += pixel.counts.pushes;
  dropped += pixel.counts.dropped;
  restarts += pixel.counts.restarts;
}

RaypipeGoldenFrame runGoldenFrame(const std::vector<uint32_t>& image,
                                  const std::vector<PrimaryRay>& rays,
                                  const RaypipeConfig& config) {
  if (image.size() < kKdHeaderWords)
    throw std::invalid_argument("a k-d memory image has at least its 16-word header");
  const KdSections sections = sectionsOf(decodeKdHeader(image.data()));
  GoldenShell<KdKind> shell(WordMemory(image), kdTraversalConfig(config));
  RaypipeGoldenFrame frame;
  frame.pixels.reserve(rays.size());
  for (const PrimaryRay& ray : rays) {
    KdResult result;
    shell.run(ray.pixel.pixelId, KdJob{ray.ray, sections}, result);
    const RaypipePixel pixel{ray.pixel,        result.hit,  result.counts.boxMisses > 0,
                             result.primitive, result.t,    result.u,
                             result.v,         result.cost, result.counts};
    frame.totals.add(pixel);
    frame.pixels.push_back(pixel);
  }
  return frame;
}

}  // namespace rtu
