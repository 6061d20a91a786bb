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
#include "kinds/core_result.h"

namespace rtu {

// One pixel of a triangle kind's result; the hit triangle's normal in the world.
FramePixel trianglePixel(const FrameScene& scene, bool hit, double distance, uint32_t cost,
                         uint32_t primitive);

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
  // The "rays", "hits" and "cost" lines.
  std::string describeHits() const { return rtu::describeHits(rays, hits, cost, maxCost); }
};

// A triangle kind's results taken one at a time (KindOutputs<Kind>::Tally, app/kind_outputs.h):
// counted, and each placed as a pixel into `frame` when given; `distance(result)` is a hit's
// distance along the world ray.
template <class Kind, class Counters>
class TriangleResults {
 public:
  explicit TriangleResults(const FrameScene& scene) : scene_(scene) {}
  template <class Distance>
  void add(const CoreKindResult& result, PixelSink* frame, Distance distance) {
    const typename Kind::Result& own = resultOfKind<Kind>(result);
    tally_.add(own);
    if (frame)
      frame->place(own.idWord,
                   trianglePixel(scene_, own.hit, distance(own), own.cost, own.primitive));
  }
  const TriangleTally<Counters>& tally() const { return tally_; }

 private:
  const FrameScene& scene_;
  TriangleTally<Counters> tally_;
};

// A count per ray (0 rays count as one).
inline double perRay(uint64_t count, size_t rays) {
  return static_cast<double>(count) / static_cast<double>(std::max<size_t>(rays, 1));
}

}  // namespace rtu
