#pragma once
// The SVO core's own settings, and the conversions at its two ends that every model shares: a
// job's float32 t-values into the core's fixed point, the finished core's result out.

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "kinds/svo/fixed_point.h"
#include "kinds/svo/ray_setup.h"
#include "kinds/svo/thesis_records.h"
#include "kinds/svo/traversal_core.h"

namespace rtu {

// The SVO kind's Config (kinds/svo/svo_kind.h): the core's number format and stack, and its job
// set-up's conversion of t-values and treatment of near-zero ray directions.
struct GoldenConfig {
  FixedFormat format;
  FloatConversion conversion = FloatConversion::Rtl;
  int stackFrames = kRtlStackFrames;
  // Ray records: direction components below epsilon times the largest count as zero.
  float epsilon = static_cast<float>(kDefaultDirectionEpsilon);

  // Throws std::invalid_argument naming the setting for a stack or format the core cannot have.
  void validate() const {
    if (stackFrames < 1 || stackFrames > kMaxStackFrames)
      throw std::invalid_argument("stack depth must be 1 to " + std::to_string(kMaxStackFrames) +
                                  " frames, got " + std::to_string(stackFrames));
    format.validate();
  }
};

// The job manager's conversion of a job's float32 t-values (appendix C.2.1).
inline std::array<int64_t, 3> convertToFixed(const std::array<uint32_t, 3>& floatBits,
                                             const FixedFormat& format,
                                             FloatConversion conversion) {
  return {floatToFixed(floatBits[0], format, conversion),
          floatToFixed(floatBits[1], format, conversion),
          floatToFixed(floatBits[2], format, conversion)};
}

// The fixed-point result of a finished core, as the RTL's result_t holds it, written over
// `result` field by field: a caller that keeps results in a column writes them there directly.
// (Copying a returned temporary stalled the loosely-timed core: the host cannot forward the
// fields just stored one by one to the wide loads of the copy.)
inline void writeResult(uint32_t idWord, const TraversalCore<FixedArith>& core,
                        TraversalResult& result) {
  result = TraversalResult{};
  result.idWord = idWord;
  result.cost = core.cost();
  result.stackOverflow = core.stackOverflow();
  result.tOverflow = core.tOverflow();
  result.belowResolution = core.belowResolution();
  result.hit = core.hit();
  if (core.hit()) {
    result.tHit = core.tHit();
    result.normal[core.normalAxis()] = core.arith().one();
  }
}

inline TraversalResult makeResult(uint32_t idWord, const TraversalCore<FixedArith>& core) {
  TraversalResult result;
  writeResult(idWord, core, result);
  return result;
}

}  // namespace rtu
