#pragma once
// What travels over the RTU's ready-valid channels. Each payload names its ray and its job
// (PayloadIds): simulation bookkeeping (statistics, the reorder buffer, merging a ray's results),
// not RTL fields.

#include <array>
#include <cstdint>
#include <variant>

#include "kinds/registry.h"
#include "kinds/svo/ray_transform.h"

namespace rtu {

// Jobs are numbered in the order they enter the job manager. For a plain frame a job is a ray,
// and both numbers are the host record's index; the scene manager issues several jobs per ray.
struct PayloadIds {
  uint64_t ray = 0;
  uint64_t job = 0;
  static PayloadIds plain(uint64_t index) { return {index, index}; }
};

struct HostPayload {
  PayloadIds ids;
  HostRecord record;
  uint64_t id() const { return ids.job; }
};

// The RTL's job_t: the id word the result carries back, and the job of the cores' kind as the
// job manager set it up (for SVO: t-values converted to fixed point). Only the core looks inside.
struct CoreJob {
  PayloadIds ids;
  uint32_t idWord = 0;
  CoreKindJob job;
  uint64_t pendingSince = 0;  // cycle the job reached the job manager's output
  uint64_t id() const { return ids.job; }
};

// The RTL's result_t: the result of the cores' kind (for SVO the thesis' record, TraversalResult),
// looked into only through kinds/core_result.h.
struct CoreResult {
  PayloadIds ids;
  CoreKindResult result;       // its cost counts the kind's states only, as the golden model's
  uint32_t blockedCycles = 0;  // cycles the core spent BLOCKED on memory for this ray
  int instance = -1;           // a scene manager's merged result: the instance hit (-1: none)
  uint64_t id() const { return ids.job; }
};

// The ray a payload belongs to, as the traces show it on every channel (class "ids").
template <class Payload>
uint64_t rayId(const Payload& payload) {
  return payload.ids.ray;
}

}  // namespace rtu
