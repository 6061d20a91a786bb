#pragma once
// Statistics of a part of a run: what a run counted after a prefix of its jobs (the counters of
// the whole run less those of a run of the prefix alone), and sums of such parts. Sampled
// simulation (sampled_run.h) counts its blocks this way, after a warm-up that is simulated but
// not counted.
//
// Each statistic combines as RtuStatistics::declaration() says (base/statistics.h): counters
// (cycles per core, cache and DRAM counts, costs, scheduler waits) are subtracted and added;
// maxima are those of the whole run, as a part has no maximum of its own to subtract.

#include <cstdint>

#include "run/rtu_statistics.h"

namespace rtu {

// `whole` less `prefix`, covering `rays` rays and `cycles` cycles.
RtuStatistics statisticsAfter(const RtuStatistics& whole, const RtuStatistics& prefix,
                              uint64_t rays, uint64_t cycles);
// Adds `part`'s counters, rays and cycles to `total` (which takes the part's configuration fields
// when it has no cores yet).
void addStatistics(RtuStatistics& total, const RtuStatistics& part);

}  // namespace rtu
