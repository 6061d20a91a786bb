#pragma once
// The scheduler's choice of a core for the pending job (thesis 6.2.2, appendix C.3), apart from
// any timing shell: the SystemC scheduler (src/sim/ca/scheduler.h) and the recurrence
// (rtu_recurrence.h, which the loosely-timed model runs on) each say what they know of the cores
// through a query, and this decides by the policy:
//  - cfa: core t mod N in cycle t, the first cycle it is idle;
//  - fa:  the lowest-numbered idle core, in the first cycle with one;
//  - rr:  the next core in turn, from the cycle it is idle.
//
// The query answers, for a core and a cycle, whether the core is idle then (Idle::Unknown when
// its shell does not know yet: the choice then waits), and from which cycle a core is idle
// (kIdleUnknown when not known):
//   struct Query { Idle in(int core, uint64_t cycle); uint64_t from(int core); };

#include <cstdint>
#include <limits>

#include "base/modulo.h"
#include "rtu/scheduling_policy.h"

namespace rtu {

enum class Idle { Yes, No, Unknown };
constexpr uint64_t kIdleUnknown = std::numeric_limits<uint64_t>::max();

class SchedulerChoice {
 public:
  static constexpr int kWait = -1;  // the policy needs a core to declare more first

  SchedulerChoice(SchedulerPolicy policy, int cores)
      : policy_(policy), cores_(cores), select_(static_cast<uint64_t>(cores)) {}

  // The core the pending job goes to, searching from `cycle` on: `cycle` is left at the dispatch
  // cycle, or at the first cycle the choice cannot decide yet (then kWait).
  template <typename Query>
  int choose(Query& query, uint64_t& cycle) const {
    switch (policy_) {
      case SchedulerPolicy::CyclicFirstAvailable: return cyclicFirstAvailable(query, cycle);
      case SchedulerPolicy::FirstAvailable: return firstAvailable(query, cycle);
      case SchedulerPolicy::RoundRobin: return roundRobin(query, cycle);
    }
    return kWait;
  }

  // The job went to `core`: round-robin's turn moves on.
  void dispatched(int core) { nextInLine_ = core + 1 == cores_ ? 0 : core + 1; }

  // The longest a job can wait for its dispatch while some core was idle in its pending cycle.
  // An idle core stays idle until a job is dispatched to it, and the pending job is the next one
  // dispatched: cfa selects every core within N cycles, fa takes an idle core at once, rr may
  // wait for its turn's core however long. (A timed shell asks whether a core was idle only for
  // waits up to this: knowing it may mean waiting for every core to declare.)
  uint64_t longestWaitWithIdleCore() const {
    switch (policy_) {
      case SchedulerPolicy::CyclicFirstAvailable: return static_cast<uint64_t>(cores_) - 1;
      case SchedulerPolicy::FirstAvailable: return 0;
      case SchedulerPolicy::RoundRobin: break;
    }
    return std::numeric_limits<uint64_t>::max();
  }

 private:
  template <typename Query>
  int cyclicFirstAvailable(Query& query, uint64_t& cycle) const {
    const int n = cores_;
    for (int core = static_cast<int>(select_.of(cycle));; ++cycle) {
      switch (query.in(core, cycle)) {
        case Idle::Yes: return core;
        case Idle::Unknown: return kWait;
        case Idle::No: break;
      }
      if (++core == n) core = 0;  // t mod N, without a division per cycle searched
    }
  }

  template <typename Query>
  int firstAvailable(Query& query, uint64_t& cycle) const {
    for (;; ++cycle) {
      bool unknown = false;
      for (int core = 0; core < cores_; ++core) {
        const Idle idle = query.in(core, cycle);
        if (idle == Idle::Unknown) unknown = true;
        if (idle == Idle::Yes) return unknown ? kWait : core;
      }
      if (unknown) return kWait;
    }
  }

  template <typename Query>
  int roundRobin(Query& query, uint64_t& cycle) const {
    const uint64_t from = query.from(nextInLine_);
    if (from == kIdleUnknown) return kWait;
    if (from > cycle) cycle = from;
    return nextInLine_;
  }

  SchedulerPolicy policy_;
  int cores_;
  Modulo select_;  // cfa: the core t mod N
  int nextInLine_ = 0;
};

}  // namespace rtu
