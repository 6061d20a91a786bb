#pragma once
// What travels over the RTU's ready-valid channels. `sequence` numbers jobs in the order the host
// submitted them; it is simulation bookkeeping (statistics, the reorder buffer), not an RTL field.

#include <array>
#include <cstdint>
#include <variant>

#include "job_setup.h"
#include "ray_transform.h"
#include "traversal_job.h"

namespace rtu {


struct HostJob {
  uint64_t sequence = 0;
  HostRecord record;
};

// The RTL's job_t: t-values converted to fixed point by the job manager.
struct CoreJob {
  uint64_t sequence = 0;
  uint32_t idWord = 0;
  uint8_t a = 0;
  std::array<int64_t, 3> t0{}, t1{};
  uint32_t root = 0;
  uint64_t pendingSince = 0;  // cycle the job reached the job manager's output
};

// The RTL's result_t.
struct CoreResult {
  uint64_t sequence = 0;
  TraversalResult result;       // its cost counts traversal states only, as the golden model's
  uint32_t blockedCycles = 0;   // cycles the core spent BLOCKED on memory for this ray
};

// The ray a payload belongs to, as the traces show it on every channel (class "ids").
inline uint64_t rayId(const HostJob& job) { return job.sequence; }
inline uint64_t rayId(const CoreJob& job) { return job.sequence; }
inline uint64_t rayId(const CoreResult& result) { return result.sequence; }

}  // namespace rtu
