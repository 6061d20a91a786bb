#pragma once
// The RTU's hardware as its configuration sizes it (issue 30 §2; docs/comparison.md,
// "Resources"): its cores (each kind's coreResources, declared in its folder and included by its
// kind header), the triangle units they share, the memory hierarchy and the result manager's
// buffers.

#include <cstdint>

#include "rtu/resource_estimate.h"
#include "sim/memory/memory_config.h"
#include "sim/rtu_config.h"

namespace rtu {

// A cache's data array (sizeBytes / 8 words of 64 bits) and tag array (sets x ways x (tag + valid
// bit), the tag the 32-bit byte address less its set and offset bits), `count` of each.
void addCache(const CacheConfig& cache, const std::string& name, int64_t count,
              ResourceEstimate& estimate);

// `cores` cores of the chosen kind, ceil(cores / triangleSharedBy) triangle units (a kind with
// one), an L1 per core and the L2 (caches), or, with ideal memory, the scene on chip as the seeds'
// designs hold it (`imageWords` words of 32 bits: the thesis' ROM, seed 004's RAMs); the result
// manager's buffer of a result record a core and the reorder buffer's `reorderCapacity` records.
ResourceEstimate rtuResources(const RtuConfig& config, uint64_t imageWords);
// The same with cores as `core` describes them (a kind's core for other jobs: the BVH's for
// two-level ones, kinds/bvh/bvh_resources.h).
ResourceEstimate rtuResources(const RtuConfig& config, uint64_t imageWords,
                              const CoreResources& core);

}  // namespace rtu
