#pragma once
// What a fixed-point format costs in accuracy: one frame traced in several formats and compared
// ray by ray with the float64 reference (reference_model.h). Misses and hits are split by
// direction, as they matter differently: a false hit is conservative (the hardware shows a voxel
// that is not in the way), a missed hit is leaky (it sees through one).

#include <cstdint>
#include <vector>

#include "kinds/svo/fixed_point.h"
#include "kinds/svo/ray_setup.h"
#include "kinds/svo/svo_memory.h"

namespace rtu {

// A ray's outcome in one format against float64.
enum class PrecisionVerdict : uint8_t {
  BothMiss,
  Agree,           // both hit the same voxel (TraversalCore::hitVoxel)
  FalseHit,        // the format hits, float64 misses
  MissedHit,       // float64 hits, the format misses
  DifferentVoxel,  // both hit, but different voxels
};

struct FormatPrecision {
  FixedFormat format;
  size_t rays = 0;
  size_t referenceHits = 0;
  size_t falseHits = 0, missedHits = 0, differentVoxels = 0;
  // The format's stack (kMaxStackFrames) overflowed: counted, not compared.
  size_t overflowRays = 0;
  size_t tOverflowRays = 0;        // flagged: a t sum wrapped (TraversalResult::tOverflow)
  size_t belowResolutionRays = 0;  // flagged: nodes narrower than a step (belowResolution)
  size_t wrongUnflagged = 0;       // wrong (hit/miss or voxel) without either flag
  // |t - t_float64| in units of the format's step 2^-fractionBits, where both hit.
  double tErrorMeanSteps = 0.0, tErrorP99Steps = 0.0, tErrorMaxSteps = 0.0;
  double meanCost = 0.0, referenceMeanCost = 0.0;  // traversal states per ray
  std::vector<PrecisionVerdict> verdicts;          // per ray, in the rays' order

  double falseHitRate() const { return rate(falseHits); }
  double missedHitRate() const { return rate(missedHits); }
  double wrongHitMissRate() const { return rate(falseHits + missedHits); }
  double differentVoxelRate() const { return rate(differentVoxels); }
  double costChange() const;  // mean cost relative to float64's, e.g. 0.01 for 1 % more

 private:
  double rate(size_t count) const { return rays ? static_cast<double>(count) / rays : 0.0; }
};

struct PrecisionStudy {
  std::vector<Ray> rays;
  uint32_t root = 0;
  FloatConversion conversion = FloatConversion::Rtl;
  double epsilon = kDefaultDirectionEpsilon;
};

// Traces the study's rays through the float64 reference once and through the golden model in each
// format (each validated first: std::invalid_argument names the one that is not).
std::vector<FormatPrecision> measurePrecision(const WordMemory& memory, const PrecisionStudy& study,
                                              const std::vector<FixedFormat>& formats);

// One notation for formats, as FixedFormat::describe prints them: QI.F, I integer bits (sign
// included) and F fraction bits ("Q16.16" -> 32 bits, 16 of them fraction). A bare "A.B" is taken
// only where one reading gives a format: as QA.B ("16.16": 16 bits cannot hold 16 fraction bits)
// or as A bits with B of them fraction ("48.32": Q16.32). Throws std::invalid_argument naming the
// text, and for an ambiguous one ("32.16") both readings.
FixedFormat parseFixedFormat(const std::string& text);

}  // namespace rtu
