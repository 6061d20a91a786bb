#pragma once
// The ray/triangle units shared by groups of cores (core.triangle.shared_by = N; docs/
// cycle-semantics.md, "Shared triangle units"): cores g*N .. g*N+N-1 share unit g (the last group
// smaller when N does not divide the cores). A core whose state issues a test (the kind's
// issuesTriangleTest) asks its unit in the state's first cycle and waits there until granted;
// the state's own cycles run from the grant. A unit grants one request in a cycle, no earlier
// than its initiation interval after its last grant; among the requests waiting in that cycle it
// takes the first core at or after the one after its last grant, cyclically within the group
// (round-robin; the group's first core before any grant). A request not granted waits for the
// unit's next free cycle. Plain C++: the memory system (memory_system.h) gives it each cycle's
// requests in cycle order, with its shared reads.

#include <cstdint>
#include <utility>
#include <vector>

namespace rtu {

class TriangleUnitArbiter {
 public:
  // `sharedBy` cores a unit (1 to cores), `interval` cycles between a unit's grants.
  TriangleUnitArbiter(int cores, int sharedBy, uint32_t interval);

  bool shared() const { return sharedBy_ > 1; }

  // The requests waiting in `cycle`, in increasing core numbers: `granted` gets the cores granted
  // in `cycle` (one per group whose unit is free), `deferred` every other with the cycle it asks
  // again in (its unit's next free cycle).
  void arbitrate(uint64_t cycle, const std::vector<int>& requests, std::vector<int>& granted,
                 std::vector<std::pair<int, uint64_t>>& deferred);

 private:
  struct Unit {
    uint64_t freeFrom = 0;  // its next grant no earlier
    int priority = 0;       // the core whose turn it is first
  };
  // The requests [first, last) of one group.
  void arbitrateGroup(uint64_t cycle, const int* first, const int* last, std::vector<int>& granted,
                      std::vector<std::pair<int, uint64_t>>& deferred);

  int cores_;
  int sharedBy_;
  uint32_t interval_;
  std::vector<Unit> units_;
};

}  // namespace rtu
