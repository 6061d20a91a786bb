#pragma once
// `rtusim compare`'s image agreement (issue 30): an architecture's frame against the float64
// reference of the same camera over the same triangles (explore/reference_frame.h), pixel by pixel:
// hit or miss, the object hit, the depth.
//   object   a triangle architecture's (and the ray pipe's) hit triangle, the mesh's index; the
//            SVO's hit voxel: the cell of the scene's grid (the cube [-1,1]^3 in 2^depth cells
//            a side) that the ray enters at its hit, for the SVO's hit and the reference's alike;
//   depth    |t - t_ref| along the unit ray, over the pixels both hit.
// The difference image colours each pixel as `precision --images` does (writePrecisionImage):
// both miss near black, agreeing hits grey, false hits blue, missed hits red, another object
// yellow.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "geometry/triangle_oracle.h"
#include "inputs/camera.h"
#include "kinds/svo/precision.h"

namespace rtu {

// What a pixel of an architecture's frame says: hit or not, the distance along the unit ray, the
// hit triangle's index in the scene's mesh (-1 for the SVO).
struct FrameHit {
  bool hit = false;
  double t = 0;
  int64_t triangle = -1;
};

// How an architecture's hit names its object: by triangle, or by voxel of a grid of `depth`.
struct ObjectRule {
  bool voxels = false;
  int depth = 0;
};

struct ImageAgreement {
  uint64_t pixels = 0, bothHit = 0, bothMiss = 0;
  uint64_t falseHits = 0, missedHits = 0, otherObject = 0;
  double meanDepthError = 0, maxDepthError = 0;  // over the pixels both hit

  uint64_t hitMissDiffer() const { return falseHits + missedHits; }
};

// Each pixel's verdict (x + y * width), `frame` of `camera` against `reference` (one per pixel);
// throws std::invalid_argument when their sizes differ.
std::vector<PrecisionVerdict> pixelVerdicts(const Camera& camera,
                                            const std::vector<FrameHit>& frame,
                                            const std::vector<std::optional<OracleHit>>& reference,
                                            const ObjectRule& rule);

ImageAgreement imageAgreement(const Camera& camera, const std::vector<FrameHit>& frame,
                              const std::vector<std::optional<OracleHit>>& reference,
                              const ObjectRule& rule);

// The grid cell (x, y, z packed) the ray of `camera`'s pixel enters at distance t.
uint64_t voxelAt(const Camera& camera, size_t pixel, double t, int depth);

}  // namespace rtu
