#include "rtu/core_statistics.h"

namespace rtu {

const StatisticGroup<CoreStatistics>& CoreStatistics::declaration() {
  using C = CoreStatistics;
  static const StatisticGroup<CoreStatistics> group =
      StatisticGroup<CoreStatistics>("a traversal core")
          .count(Statistic("jobs", "jobs", "jobs the core took"), &C::jobs)
          .count(Statistic("busy", "cycles",
                           "cycles in the traversal's states, outside IDLE, OUT and BLOCKED: the "
                           "cost of its rays"),
                 &C::busyCycles)
          .count(Statistic("blocked", "cycles", "cycles BLOCKED on memory"), &C::blockedCycles)
          .count(Statistic("handover", "cycles",
                           "cycles in OUT: a result waiting for the result manager"),
                 &C::outCycles)
          .count(Statistic("stack_overflows", "rays",
                           "rays that ran out of stack frames, reported as misses (result flag 1)")
                     .runTotal()
                     .reportedWhenNotZero(),
                 &C::stackOverflows)
          .count(Statistic("t_overflows", "rays",
                           "rays with t-values beyond the fixed-point range (result flag 2)")
                     .runTotal()
                     .reportedWhenNotZero("t-values beyond the fixed-point range; flag 2"),
                 &C::tOverflows);
  return group;
}

}  // namespace rtu
