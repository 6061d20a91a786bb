#pragma once
// Frames as a running unit sees them (the warm_frames setting, `--warm-frames N`): a frame of a
// unit that renders frame after frame starts from the caches the frames before it left, not from
// cold ones. The caches are brought there by functional warming (cache_warmer.h): N untimed passes
// over the frame's own records, each ray touching the lines of its accesses in the L1 of core
// (ray mod cores) and, on an L1 miss, in the L2. docs/fidelity.md, "Warm frames", measures it
// against frames simulated back to back.

#include <optional>
#include <vector>

#include "kinds/host_record.h"
#include "rtu/word_memory.h"
#include "sim/memory/cache_contents.h"
#include "sim/rtu_config.h"

namespace rtu {

// The caches after config.warmFrames frames of `records`, or nothing when the run starts cold
// (no warm frames, or ideal memory).
std::optional<CacheContents> warmedCaches(const WordMemory& memory,
                                          const std::vector<HostRecord>& records,
                                          const RtuConfig& config);

}  // namespace rtu
