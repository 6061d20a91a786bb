#pragma once
// What a traversal core of any kind counts, in any model (the SystemC core, the recurrence's
// cores), and the declaration of it (base/statistics.h): per core its jobs and the cycles it spent
// busy, blocked on memory and handing over its result, and the counters of the registry's kinds
// (CoreKinds::Counters: for SVO, the rays whose traversal overflowed, counted by
// SvoKind::count). The counters are summed with the rest but written by the run, once, for the
// kind its cores are of (RtuStatistics, CoreKinds::runCounters). A job's cost is its cycles
// outside IDLE, OUT and BLOCKED.

#include <cstdint>

#include "base/statistics.h"
#include "kinds/registry.h"

namespace rtu {

struct CoreStatistics : CoreKinds::Counters {
  uint64_t jobs = 0;
  uint64_t busyCycles = 0;       // the kind's working states (the jobs' cost)
  uint64_t blockedCycles = 0;    // BLOCKED
  uint64_t outCycles = 0;        // OUT: result waiting for the result manager
  uint64_t unitStallCycles = 0;  // a test waiting for its shared triangle unit

  static const StatisticGroup<CoreStatistics>& declaration() {
    using C = CoreStatistics;
    static const StatisticGroup<CoreStatistics> group =
        StatisticGroup<CoreStatistics>("a traversal core")
            .count(Statistic("jobs", "jobs", "jobs the core took"), &C::jobs)
            .count(Statistic("busy", "cycles",
                             "cycles in the traversal's states, outside IDLE, OUT and BLOCKED: "
                             "the cost of its rays"),
                   &C::busyCycles)
            .count(Statistic("blocked", "cycles", "cycles BLOCKED on memory"), &C::blockedCycles)
            .count(Statistic("handover", "cycles",
                             "cycles in OUT: a result waiting for the result manager"),
                   &C::outCycles)
            .count(Statistic("triangle_unit_stall", "cycles",
                             "cycles a test waited for its shared ray/triangle unit "
                             "(core.triangle.shared_by; not in busy or blocked)"),
                   &C::unitStallCycles)
            .combinedBase<CoreKinds::Counters>();
    return group;
  }
};

}  // namespace rtu
