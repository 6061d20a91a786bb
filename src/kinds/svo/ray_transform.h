#pragma once
// The job manager of an RTU with animated models (thesis section 6.2.1, stages one and two): a
// world-space ray record and its model's header (model_header.h) become a traversal job. Untimed
// and shared: the golden model and the SystemC job manager both call rayRecordToJob, so the
// operation order below defines the bit-exact result.
//
// Every value is float32, every operation rounds to nearest even on its own (a multiply-add is a
// multiply, rounded, then an add, rounded: no fused multiply-add; the project builds in ISO C++
// mode, where GCC does not contract, and each operation is its own statement). With the header's
// T, R^T (rows m_i) and s = 1/S:
//
//   1. v = o - T                                   (per axis)
//   2. q_i = (m_i0 v_0 + m_i1 v_1) + m_i2 v_2,      o'_i = s_i q_i
//   3. e_i = (m_i0 d_0 + m_i1 d_1) + m_i2 d_2,      d'_i = s_i e_i
//   4. m = max_k |d'_k|,  tau = max(epsilon m, FLT_MIN)
//   5. per axis k:  |d'_k| < tau:  d'_k = tau                   (+tau, never mirrored)
//                   d'_k < 0:      d'_k = -d'_k, o'_k = -o'_k, a |= 1 << k
//   6. r = 1 / d'_k,  p = (-o'_k) r,  t0_k = p - r,  t1_k = p + r      (eq. 6.6)
//
// The direction is not normalised: t keeps the world units of d (a unit d gives world distances,
// and a non-uniform scale does not distort t). Step 4 is the driver's "replace zero components by
// epsilon" made independent of |d|: components smaller than epsilon times the largest count as
// zero, so the replacement tilts the ray by at most about epsilon radians whatever the length of
// d, scaling d by a power of two scales every t exactly, and 1/d' stays finite (tau >= FLT_MIN).
// Mirroring negates o' because the model's cube is centred on the origin (eq. 6.4 with c = 0).
//
// For a record and header that pass their validate(), no t-value is NaN and t0 <= t1 on every
// axis: |o|, |d|, |T| <= 2^64 and 1/S <= 2^32 keep o' and d' below 2^100, and 0 < r <= 2^126, so
// at worst p overflows to an infinity that t0 and t1 share.

#include <array>
#include <cstdint>
#include <vector>

#include "kinds/svo/model_header.h"
#include "kinds/svo/ray_setup.h"
#include "kinds/svo/svo_memory.h"
#include "kinds/svo/thesis_records.h"

namespace rtu {

// The thesis's input ray packet (section 5.2): a world-space ray and the model to trace.
struct RayRecord {
  uint32_t id = 0;  // 28 bits: the job manager packs a into bits 30:28 of the job word
  std::array<float, 3> origin{0.0f, 0.0f, 0.0f};
  std::array<float, 3> direction{0.0f, 0.0f, 1.0f};
  uint32_t modelAddress = 0;  // word address of the model header

  // Throws std::runtime_error for an id over 28 bits, a NaN or infinite component, a component
  // beyond kMaxModelCoordinate, or a zero direction.
  void validate() const;
};

// The record for a double-precision ray: direction normalised in double, then rounded to float32.
RayRecord makeRayRecord(uint32_t id, const Ray& ray, uint32_t modelAddress);

// Steps 1 to 6 above. `record` and `header` must be valid (the hardware checks neither); throws
// std::invalid_argument unless 0 < epsilon < 1.
TValueRecord rayRecordToJob(const RayRecord& record, const ModelHeader& header,
                            float epsilon = static_cast<float>(kDefaultDirectionEpsilon));

// Reads each model header the records name from `memory` (once per address, as the job manager
// caches them for a frame) and sets up every job. Throws std::runtime_error naming the record for
// an invalid record or header.
std::vector<TValueRecord> rayRecordsToJobs(const WordMemory& memory,
                                           const std::vector<RayRecord>& records, float epsilon);

}  // namespace rtu
