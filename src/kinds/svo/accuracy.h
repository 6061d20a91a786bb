#pragma once
// How far the fixed-point golden model is from the float64 reference on the same rays.

#include <cstdint>
#include <string>
#include <vector>

#include "kinds/svo/golden_model.h"
#include "kinds/svo/ray_setup.h"

namespace rtu {

struct AccuracyReport {
  double tTolerance = 0.0;
  size_t rays = 0;
  size_t referenceHits = 0;
  // Rays the golden model flagged as overflowing its stack (traced only with
  // --allow-stack-overflow): ended as misses, they are not compared with the reference.
  size_t stackOverflows = 0;
  size_t hitMismatches = 0;  // one model hits, the other misses
  size_t edgeHits = 0;       // both hit at the same t, but name different faces: an edge
  size_t tOutliers = 0;      // both hit, t differs by more than the tolerance
  double maxTError = 0.0;    // over the pixels where both hit
  double meanTError = 0.0;
  uint64_t fixedCost = 0;  // total cost of each model, to see traversal differences
  uint64_t referenceCost = 0;

  size_t compared() const { return rays - stackOverflows; }
  size_t agreeing() const { return compared() - hitMismatches - tOutliers; }
  double agreement() const {
    return compared() ? static_cast<double>(agreeing()) / compared() : 1.0;
  }
  std::string describe() const;
};

// Traces every ray through the golden model (float32 job set-up, fixed point) and the float64
// reference (double set-up and arithmetic). A pixel agrees when both miss, or both hit with
// |t_fixed - t_float64| <= tTolerance. Where the t-values agree but the faces differ, the ray hit
// an edge or corner (two entry planes at the same t) and rounding broke the tie differently:
// counted as edgeHits, and agreeing.
AccuracyReport measureAccuracy(const WordMemory& memory, uint32_t root,
                               const std::vector<Ray>& rays, const GoldenConfig& config,
                               double epsilon, double tTolerance);

// Number of results that differ in any field.
size_t countDifferences(const std::vector<TraversalResult>& a,
                        const std::vector<TraversalResult>& b);

}  // namespace rtu
