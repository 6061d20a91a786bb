#pragma once
// The untimed, bit-exact model of the RTU: every job's result and cost as the thesis RTL
// computes them, without simulating time. It is the reference for every timed model.

#include <vector>

#include "kinds/svo/fixed_point.h"
#include "kinds/svo/ray_transform.h"
#include "kinds/svo/svo_memory.h"
#include "kinds/svo/traversal_core.h"
#include "kinds/svo/traversal_job.h"

namespace rtu {

struct GoldenConfig {
  FixedFormat format;
  FloatConversion conversion = FloatConversion::Rtl;
  int stackFrames = kRtlStackFrames;
};

class GoldenModel {
 public:
  GoldenModel(WordMemory memory, GoldenConfig config);

  TraversalResult trace(const TraversalJob& job);
  std::vector<TraversalResult> traceAll(const std::vector<TraversalJob>& jobs);
  // World-space rays of animated models: each job is set up from its model's header in memory
  // (rayRecordsToJobs), then traced. Throws std::runtime_error for an invalid record or header.
  std::vector<TraversalResult> traceRays(const std::vector<RayRecord>& records, float epsilon);

  const GoldenConfig& config() const { return config_; }
  // The voxel the last traced job hit (TraversalCore::hitVoxel), when it hit.
  uint64_t lastHitVoxel() const { return core_.hitVoxel(); }

 private:
  WordMemory memory_;
  GoldenConfig config_;
  TraversalCore<FixedArith> core_;
};

// The job manager's conversion of a job's float32 t-values (appendix C.2.1).
std::array<int64_t, 3> convertToFixed(const std::array<uint32_t, 3>& floatBits,
                                      const FixedFormat& format, FloatConversion conversion);

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
