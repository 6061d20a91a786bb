#pragma once
// What the triangle kinds' outputs of a rendered frame share (issue 28; each kind's own are in
// kinds/<kind>/app/): their pixels and hit report lines, from the results of a frame on the scene
// frame_scene.h built for the kind (`render --core bvh`, `--core bih`, `--core kd`). A pixel takes
// the hit's distance along the world ray (the kind's `distance` of a result) and the normal of the
// hit triangle of the scene's mesh (every kind's `primitive` is the mesh's triangle index).

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "app/frame_images.h"
#include "explore/frame_scene.h"

namespace rtu {

// One pixel of a triangle kind's result; the hit triangle's normal in the world.
FramePixel trianglePixel(const FrameScene& scene, bool hit, double distance, uint32_t cost,
                         uint32_t primitive);

// The frame's pixels from results whose id words are pixel indices; `distance(result)` is a hit's
// distance along the world ray.
template <class Result, class Distance>
RenderedFrame triangleFrame(const Camera& camera, const FrameScene& scene,
                            const std::vector<Result>& results, Distance distance) {
  RenderedFrame frame(camera);
  for (const Result& result : results)
    frame.place(result.idWord,
                trianglePixel(scene, result.hit, distance(result), result.cost, result.primitive));
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

// A count per ray (0 rays count as one).
inline double perRay(uint64_t count, size_t rays) {
  return static_cast<double>(count) / static_cast<double>(std::max<size_t>(rays, 1));
}

// The sum of the results' counts, as the kind's counters.
template <class Counters, class Result>
Counters countersOf(const std::vector<Result>& results) {
  Counters counters;
  for (const Result& result : results) counters.add(result.counts);
  return counters;
}

}  // namespace rtu
