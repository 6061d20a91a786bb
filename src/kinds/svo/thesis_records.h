#pragma once
// The thesis' records of a job and its result (appendix C.6, job_t and result_t), independent of
// how they travel: host buffers, ready-valid channels or TLM payloads. The words "job" name, in
// rtusim: a TValueRecord (the host's t-value record of a ray), a HostRecord (that or a world-space
// ray, kinds/host_record.h), a HostPayload (a host record on its way to the job manager), a
// kind's Job (what the job manager hands a core: SvoJob) inside a CoreJob (its payload), and a
// JobTiming (a job as the recurrence times it). Worker processes and Slurm array tasks are
// "workers" and "tasks".

#include <array>
#include <cstdint>

#include "rtu/host_link.h"
#include "rtu/ray_record.h"

namespace rtu {

// The host's t-value record of a ray: the traversal job with the t-parameters still in float32,
// as the host driver sends them (appendix F): the job manager converts them to fixed point.
struct TValueRecord {
  uint32_t id = 0;  // 28 bits: the driver packs `a` into bits 30:28 beside it
  uint8_t a = 0;    // direction coefficient: bit k set when direction k was negative
  // A ray record's span (rtu/ray_span.h), which its set-up keeps; the thesis driver's records have
  // none (RaySpan::Line). Beside `a`, in what would be padding.
  RaySpan span = RaySpan::Line;
  std::array<uint32_t, 3> t0Bits{};  // float32 bit patterns of t0x, t0y, t0z
  std::array<uint32_t, 3> t1Bits{};
  uint32_t root = 0;  // word address of the root descriptor

  static constexpr uint32_t kMaxId = kMaxRayId;
  static constexpr const char* kName = "t-value record";
  // The first word of the host record; the RTL carries it unchanged into the result. Bit 31 marks
  // an any-hit ray (rtu/ray_span.h).
  uint32_t idWord() const {
    return id | static_cast<uint32_t>(a) << 28 | (span == RaySpan::AnyHit ? kAnyHitBit : 0u);
  }
};

// Result records of formats over 32 bits: 12 words, t and the normal 64 bits each
// (docs/inputs-jobs.md); 8 words, as a job's, up to 32 bits.
constexpr uint64_t kWideResultRecordBytes = 48;
inline uint64_t resultRecordBytes(int totalBits) {
  return totalBits > 32 ? kWideResultRecordBytes : kHostRecordBytes;
}

struct TraversalResult {
  uint32_t idWord = 0;  // the job's first word, a bits included, exactly as the RTL returns it
  bool hit = false;
  int64_t tHit = 0;                 // fixed point; 0 on a miss
  std::array<int64_t, 3> normal{};  // 1.0 on the entry face's axis (mirrored space); 0 on a miss
  uint32_t cost = 0;                // cycles spent in INIT, EVAL, NEXT, PUSH and POP
  bool stackOverflow = false;       // traversal needed more stack frames than configured
  bool tOverflow = false;           // t-values beyond the format's range (wrapped or saturated)
  bool belowResolution = false;     // descended into nodes narrower than the format's step

  uint32_t id() const { return idWord & TValueRecord::kMaxId; }
  bool operator==(const TraversalResult& other) const {
    return idWord == other.idWord && hit == other.hit && tHit == other.tHit &&
           normal == other.normal && cost == other.cost && stackOverflow == other.stackOverflow &&
           tOverflow == other.tOverflow && belowResolution == other.belowResolution;
  }
  bool operator!=(const TraversalResult& other) const { return !(*this == other); }
};

}  // namespace rtu
