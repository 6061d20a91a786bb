#pragma once
// The triangle kinds' own outputs of a rendered frame (issue 28): their pixels and report lines,
// from the results of a frame on the scene frame_scene.h built for the kind (`render --core bvh`,
// `--core bih`, `--core kd`). A pixel takes the hit's distance along the world ray (a BIH result's
// `distance`, its t being in grid units) and the normal of the hit triangle of the scene's mesh
// (every kind's `primitive` is the mesh's triangle index).

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "app/frame_images.h"
#include "explore/frame_scene.h"
#include "kinds/bih/bih_kind.h"
#include "kinds/bvh/bvh_kind.h"
#include "kinds/kd/kd_kind.h"

namespace rtu {

// One pixel of a triangle kind's result; the hit triangle's normal in the world.
FramePixel trianglePixel(const FrameScene& scene, bool hit, double distance, uint32_t cost,
                         uint32_t primitive);

inline double worldDistance(const BvhResult& result) { return result.t; }
inline double worldDistance(const BihResult& result) { return result.distance; }
inline double worldDistance(const KdResult& result) { return result.t; }

// The frame's pixels from results whose id words are pixel indices.
template <class Result>
RenderedFrame triangleFrame(const Camera& camera, const FrameScene& scene,
                            const std::vector<Result>& results) {
  RenderedFrame frame(camera);
  for (const Result& result : results)
    frame.place(result.idWord, trianglePixel(scene, result.hit, worldDistance(result), result.cost,
                                             result.primitive));
  return frame;
}

// "rays", "hits" and "cost" report lines of a frame's results.
std::string describeHits(size_t rays, uint64_t hits, uint64_t cost, uint32_t maxCost);

template <class Result>
std::string describeTriangleHits(const std::vector<Result>& results) {
  uint64_t hits = 0, cost = 0;
  uint32_t maxCost = 0;
  for (const Result& result : results) {
    hits += result.hit;
    cost += result.cost;
    maxCost = std::max(maxCost, result.cost);
  }
  return describeHits(results.size(), hits, cost, maxCost);
}

// Hits, mean cost and the kind's counters per ray, as report lines; for the BIH the triangle unit's
// fill rate, its tests' issue cycles (`unitInterval` each) over the rays' cycles (their costs).
std::string describeBvhResults(const std::vector<BvhResult>& results);
std::string describeBihResults(const std::vector<BihResult>& results, uint32_t unitInterval);
std::string describeKdResults(const std::vector<KdResult>& results);

}  // namespace rtu
