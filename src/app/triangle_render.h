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

// What a triangle kind's report counts of its results, summed one result at a time (so a frame's
// results can be counted as they leave a run): hits, costs and the kind's counters.
template <class Counters>
struct TriangleTally {
  size_t rays = 0;
  uint64_t hits = 0, cost = 0;
  uint32_t maxCost = 0;
  Counters counters;

  template <class Result>
  void add(const Result& result) {
    ++rays;
    hits += result.hit;
    cost += result.cost;
    maxCost = std::max(maxCost, result.cost);
    counters.add(result.counts);
  }
  template <class Result>
  static TriangleTally of(const std::vector<Result>& results) {
    TriangleTally tally;
    for (const Result& result : results) tally.add(result);
    return tally;
  }
};

// Hits, mean cost and the kind's counters per ray, as report lines; for the BIH the triangle unit's
// fill rate, its tests' issue cycles (`unitInterval` each) over the rays' cycles (their costs).
std::string describeBvhResults(const TriangleTally<BvhCounters>& tally);
std::string describeBihResults(const TriangleTally<BihCounters>& tally, uint32_t unitInterval);
std::string describeKdResults(const TriangleTally<KdCounters>& tally);
inline std::string describeBvhResults(const std::vector<BvhResult>& results) {
  return describeBvhResults(TriangleTally<BvhCounters>::of(results));
}
inline std::string describeBihResults(const std::vector<BihResult>& results,
                                      uint32_t unitInterval) {
  return describeBihResults(TriangleTally<BihCounters>::of(results), unitInterval);
}
inline std::string describeKdResults(const std::vector<KdResult>& results) {
  return describeKdResults(TriangleTally<KdCounters>::of(results));
}

}  // namespace rtu
