#pragma once
// The SVO job manager's set-up of a world-space ray record (thesis section 6.2.1): the record
// moved into its model's space as every kind's is (rtu/model_transform.h, steps 1 to 3), then
// t-values against the model's cube [-1,1]^3 (steps 4 to 6). Untimed and shared: the golden model
// and the SystemC job manager both call rayRecordToJob, so the operation order defines the
// bit-exact result. Every value is float32, every operation rounded on its own, as in
// rtu/model_transform.h. With o', d' the model-space ray:
//
//   4. m = max_k |d'_k|,  tau = max(epsilon m, FLT_MIN)
//   5. per axis k:  |d'_k| < tau:  d'_k = tau                   (+tau, never mirrored)
//                   d'_k < 0:      d'_k = -d'_k, o'_k = -o'_k, a |= 1 << k
//   6. r = 1 / d'_k,  p = (-o'_k) r,  t0_k = p - r,  t1_k = p + r      (eq. 6.6)
//
// Step 4 is the driver's "replace zero components by epsilon" made independent of |d|:
// components smaller than epsilon times the largest count as zero, so the replacement tilts the
// ray by at most about epsilon radians whatever the length of d, scaling d by a power of two
// scales every t exactly, and 1/d' stays finite (tau >= FLT_MIN). Mirroring negates o' because
// the model's cube is centred on the origin (eq. 6.4 with c = 0).
//
// For a record and header that pass their validate(), no t-value is NaN and t0 <= t1 on every
// axis: |o|, |d|, |T| <= 2^64 and 1/S <= 2^32 keep o' and d' below 2^100, and 0 < r <= 2^126, so
// at worst p overflows to an infinity that t0 and t1 share.

#include <array>
#include <cstdint>
#include <vector>

#include "kinds/svo/ray_setup.h"
#include "kinds/svo/svo_memory.h"
#include "kinds/svo/thesis_records.h"
#include "rtu/model_header.h"
#include "rtu/model_transform.h"
#include "rtu/ray_record.h"

namespace rtu {

// Steps 1 to 6. `record` and `header` must be valid (the hardware checks neither); throws
// std::invalid_argument unless 0 < epsilon < 1.
TValueRecord rayRecordToJob(const RayRecord& record, const ModelHeader& header,
                            float epsilon = static_cast<float>(kDefaultDirectionEpsilon));

// Reads each model header the records name from `memory` (once per address, as the job manager
// caches them for a frame) and sets up every job. Throws std::runtime_error naming the record for
// an invalid record or header.
std::vector<TValueRecord> rayRecordsToJobs(const WordMemory& memory,
                                           const std::vector<RayRecord>& records, float epsilon);

}  // namespace rtu
