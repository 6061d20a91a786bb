#pragma once
// The ray pipe's golden frame (issue 29): every ray the primary ray generator issues
// (primary_rays.h) through the golden k-d traversal (kinds/kd/kd_traversal.h, run as KdKind by the
// untimed shell) over a scene's memory image, with the pipe's traversal settings (its short-stack
// depth, divider and t_max clamp). What the shader receives of each ray, in issue order, and the
// frame's totals: the bit-exact answers the pipe's timed models must give.

#include <cstdint>
#include <vector>

#include "kinds/kd/kd_traversal.h"
#include "raypipe/primary_rays.h"
#include "raypipe/raypipe_config.h"
#include "rtu/word_memory.h"

namespace rtu {

// The golden traversal's settings from the pipe's.
KdTraversalConfig kdTraversalConfig(const RaypipeConfig& config);

struct RaypipePixel {
  PrgPixel pixel;
  bool hit = false, boxMiss = false;
  uint32_t primitive = 0;  // the hit triangle's id; 0 on a miss
  float t = 0, u = 0,
        v = 0;        // the seed's: t along the PRG's direction, u weighs A, v B; 0 on a miss
  uint32_t cost = 0;  // the golden traversal's states
  KdRayCounts counts;
};

struct RaypipeFrameTotals {
  uint64_t rays = 0, boxMisses = 0, hits = 0;
  uint64_t nodes = 0, leaves = 0, triangleTests = 0, pushes = 0, dropped = 0, restarts = 0;
  void add(const RaypipePixel& pixel);
};

struct RaypipeGoldenFrame {
  std::vector<RaypipePixel> pixels;  // in issue order
  RaypipeFrameTotals totals;
};

// `image` is a k-d memory image (kinds/kd/kd_image.h) that outlives the call.
RaypipeGoldenFrame runGoldenFrame(const std::vector<uint32_t>& image,
                                  const std::vector<PrimaryRay>& rays, const RaypipeConfig& config);

}  // namespace rtu
