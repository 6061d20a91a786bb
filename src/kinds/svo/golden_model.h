#pragma once
// The untimed, bit-exact model of the RTU: every job's result and cost as the thesis RTL
// computes them, without simulating time. It is the reference for every timed model: the SVO
// kind's job set-up in front of the untimed shell every kind shares (rtu/golden_shell.h).

#include <vector>

#include "kinds/svo/golden_config.h"
#include "kinds/svo/ray_transform.h"
#include "kinds/svo/svo_kind.h"
#include "kinds/svo/thesis_records.h"
#include "rtu/golden_shell.h"

namespace rtu {

class GoldenModel {
 public:
  GoldenModel(WordMemory memory, GoldenConfig config);

  TraversalResult trace(const TValueRecord& job);
  std::vector<TraversalResult> traceAll(const std::vector<TValueRecord>& jobs);
  // World-space rays of animated models: each job is set up from its model's header in memory
  // (rayRecordsToJobs), then traced. Throws std::runtime_error for an invalid record or header.
  std::vector<TraversalResult> traceRays(const std::vector<RayRecord>& records, float epsilon);

  const GoldenConfig& config() const { return config_; }
  // The voxel the last traced job hit (TraversalCore::hitVoxel), when it hit.
  uint64_t lastHitVoxel() const { return shell_.behaviour().hitVoxel(); }

 private:
  GoldenConfig config_;
  GoldenShell<SvoKind> shell_;
};

}  // namespace rtu
