#include "run/recurrence_results.h"

#include <tuple>
#include <utility>

#include "kinds/core_result.h"
#include "run/recurrence_statistics.h"

namespace rtu {
namespace {

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
  RecurrenceStatistics statistics(config);
  for (size_t job : timing.hostOrder) {
    const JobCycles cycles{job,
                           timing.acceptCycles[job],
                           timing.pendingCycles[job],
                           timing.dispatchCycles[job],
                           timing.cores[job],
                           timing.handoverCycles[job],
                           timing.drainCycles[job]};
    statistics.add(cycles, results[job], blocked.empty() ? 0 : blocked[job]);
  }
  run.statistics =
      statistics.finish(RecurrenceTotals{timing.totalCycles, timing.resultBuffersMaxFull});
  if (blocked.empty()) blocked.assign(results.size(), 0);
  arrangeInHostOrder(timing.hostOrder, results, timing.drainCycles, blocked);
  run.results = std::move(results);
  run.arrivalCycles = std::move(timing.drainCycles);
  run.blockedCycles = std::move(blocked);
  run.jobIndices = std::move(timing.hostOrder);
  return run;
}

}  // namespace rtu
