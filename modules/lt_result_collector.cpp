#include "lt_result_collector.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scheduler_choice.h"

namespace rtu {
namespace {

constexpr uint64_t kNoDrain = std::numeric_limits<uint64_t>::max();

uint64_t cyclesPerRecord(const HostLinkConfig& link) {
  if (link.bytesPerCycle <= 0) return 0;
  return static_cast<uint64_t>(std::ceil(static_cast<double>(link.recordBytes) / link.bytesPerCycle));
}

}  // namespace

LtResultCollector::LtResultCollector(sc_core::sc_module_name name, int cores,
                                     const HostLinkConfig& output, size_t expected,
                                     const LtTime& time)
    : sc_core::sc_module(name),
      time_(time),
      coreCount_(static_cast<uint64_t>(cores)),
      linkCycles_(cyclesPerRecord(output)),
      lastDrain_(coreCount_, kNoDrain),
      cores_(coreCount_) {
  arrivals_.reserve(expected);
}

uint64_t LtResultCollector::handOver(int core, uint64_t outCycle, const CoreResult& result) {
  const size_t c = static_cast<size_t>(core);
  // No core is behind simulated time: what lies before it is settled.
  if (linkCycles_ > 0) linkSlots_.forgetBefore(time_.now() / linkCycles_);
  buffered_.settle(time_.now());
  const uint64_t handover =
      lastDrain_[c] == kNoDrain ? outCycle : std::max(outCycle, lastDrain_[c] + 1);
  const uint64_t drain = drainCycle(core, handover + 1);
  lastDrain_[c] = drain;
  buffered_.enter(handover + 1);
  buffered_.leave(drain + 2);
  arrivals_.push_back({drain, result});

  CoreStatistics& stats = cores_[c];
  ++stats.jobs;
  stats.busyCycles += result.result.cost;
  stats.blockedCycles += result.blockedCycles;
  stats.outCycles += handover + 1 - outCycle;
  stats.stackOverflows += result.result.stackOverflow;
  stats.tOverflows += result.result.tOverflow;
  return handover + 1;
}

// The select counter reaches `core` in the cycles t = core mod N; the drain is the first of them
// whose slot of the output link is free.
uint64_t LtResultCollector::drainCycle(int core, uint64_t from) {
  uint64_t cycle = selectCounterReaches(core, static_cast<int>(coreCount_), from);
  if (linkCycles_ == 0) return cycle;
  while (!linkSlots_.takeIfFree(cycle / linkCycles_)) cycle += coreCount_;
  return cycle;
}

}  // namespace rtu
