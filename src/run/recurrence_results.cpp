#include "run/recurrence_results.h"

#include <algorithm>
#include <array>
#include <tuple>
#include <utility>

#include "kinds/core_result.h"

namespace rtu {
namespace {

// Whether some core was idle in the cycle a job became pending (eq. 6.7's case), asked in job
// order. A core is busy from the cycle after its dispatch to its handover; every earlier job was
// dispatched before that cycle, and a core's earlier jobs handed over before its last one was
// dispatched, so only each core's last job so far can still be busy.
class IdleCores {
 public:
  explicit IdleCores(int cores) : busyUntil_(static_cast<size_t>(cores), 0) {}
  bool anyAt(uint64_t cycle) const {
    return std::any_of(busyUntil_.begin(), busyUntil_.end(),
                       [cycle](uint64_t until) { return until <= cycle; });
  }
  void ran(int core, uint64_t handover) { busyUntil_[static_cast<size_t>(core)] = handover + 1; }

 private:
  std::vector<uint64_t> busyUntil_;  // per core: its last job's handover + 1 (0: none yet)
};

// Sorts values that are nearly in order, by moving each late one back to its place: few moves
// each. Should they be far off, a sort finishes once the moves reach a few per value.
void sortNearlySorted(std::vector<uint64_t>& values) {
  uint64_t movesLeft = 8 * values.size();
  for (size_t late = 1; late < values.size(); ++late) {
    const uint64_t value = values[late];
    size_t place = late;
    for (; place > 0 && values[place - 1] > value; --place) values[place] = values[place - 1];
    values[place] = value;
    if (late - place >= movesLeft) return std::sort(values.begin(), values.end());
    movesLeft -= late - place;
  }
}

// The most result buffers full at once, as the result manager counts them: a result counts from
// the cycle after its handover to the cycle after it drained. Drains come in host order, so their
// ends are in order; the handovers follow the dispatches, nearly in order. Sorts the handover
// column in place (a frame's copy would be megabytes of fresh pages): nothing reads it after.
uint64_t maxBuffersFull(RecurrenceRun& run) {
  std::vector<uint64_t>& handovers = run.handoverCycles;
  sortNearlySorted(handovers);
  uint64_t full = 0, most = 0;
  size_t ended = 0;
  const auto end = [&run](size_t k) { return run.drainCycles[run.hostOrder[k]] + 1; };
  for (uint64_t handover : handovers) {
    for (; ended < run.hostOrder.size() && end(ended) <= handover; ++ended) --full;
    most = std::max(most, ++full);
  }
  return most;
}

// Sorts the run's handover column (maxBuffersFull).
RtuStatistics statisticsOf(RecurrenceRun& run, const std::vector<CoreKindResult>& results,
                           const std::vector<uint32_t>& blocked, const RtuConfig& config) {
  RtuStatistics stats = RtuStatistics::of(config);
  stats.rays = results.size();
  stats.totalCycles = run.totalCycles;
  stats.coreTimes.resize(static_cast<size_t>(config.cores));
  IdleCores idleCores(config.cores);
  std::array<uint64_t, 256> shortWaits{};  // jobs by wait: no map look-up per job
  for (size_t j = 0; j < results.size(); ++j) {
    const CoreKindResult& result = results[j];
    const uint32_t cost = resultCost(result);
    const uint64_t blockedCycles = blocked.empty() ? 0 : blocked[j];
    CoreStatistics& core = stats.coreTimes[static_cast<size_t>(run.cores[j])];
    ++core.jobs;
    core.busyCycles += cost;
    core.blockedCycles += blockedCycles;
    core.outCycles +=
        run.handoverCycles[j] + 1 - (run.dispatchCycles[j] + 1 + cost + blockedCycles);
    countResult(result, core);
    stats.count(result, blockedCycles);
    const uint64_t wait = run.dispatchCycles[j] - run.pendingCycles[j];
    stats.jobManagerStallCycles += wait;
    if (wait < shortWaits.size())
      ++shortWaits[wait];
    else
      ++stats.waitHistogram[wait];
    stats.maxWait = std::max(stats.maxWait, wait);
    // Only a wait that would raise the maximum needs the cores asked.
    if (wait > stats.maxWaitWithReadyCore && idleCores.anyAt(run.pendingCycles[j]))
      stats.maxWaitWithReadyCore = wait;
    idleCores.ran(run.cores[j], run.handoverCycles[j]);
  }
  for (uint64_t wait = 0; wait < shortWaits.size(); ++wait)
    if (shortWaits[wait] > 0) stats.waitHistogram[wait] += shortWaits[wait];
  stats.resultBuffersMaxFull = maxBuffersFull(run);
  return stats;
}

// Columns by job index, rearranged into host order in place, all in one walk along the
// permutation's cycles: a frame's columns are tens of MB, which copies would take in fresh pages.
template <typename... Columns>
void arrangeInHostOrder(const std::vector<size_t>& hostOrder, Columns&... columns) {
  std::vector<bool> placed(hostOrder.size());
  for (size_t start = 0; start < hostOrder.size(); ++start) {
    if (placed[start]) continue;
    auto first = std::make_tuple(std::move(columns[start])...);
    size_t place = start;
    for (size_t from = hostOrder[place]; from != start; place = from, from = hostOrder[place]) {
      ((columns[place] = std::move(columns[from])), ...);
      placed[place] = true;
    }
    std::tie(columns[place]...) = std::move(first);
    placed[place] = true;
  }
}

}  // namespace

RtuRun recurrenceResults(RecurrenceRun timing, std::vector<CoreKindResult> results,
                         std::vector<uint32_t> blocked, const RtuConfig& config) {
  RtuRun run;
  run.totalCycles = timing.totalCycles;
  run.statistics = statisticsOf(timing, results, blocked, config);
  if (blocked.empty()) blocked.assign(results.size(), 0);
  arrangeInHostOrder(timing.hostOrder, results, timing.drainCycles, blocked);
  run.results = std::move(results);
  run.arrivalCycles = std::move(timing.drainCycles);
  run.blockedCycles = std::move(blocked);
  run.jobIndices = std::move(timing.hostOrder);
  return run;
}

}  // namespace rtu
