#include "sim/ca/triangle_unit_arbiter.h"

#include <cstddef>

namespace rtu {

TriangleUnitArbiter::TriangleUnitArbiter(int cores, int sharedBy, uint32_t interval)
    : cores_(cores), sharedBy_(sharedBy), interval_(interval) {
  for (int first = 0; first < cores_; first += sharedBy_) units_.push_back(Unit{0, first});
}

void TriangleUnitArbiter::arbitrate(uint64_t cycle, const std::vector<int>& requests,
                                    std::vector<int>& granted,
                                    std::vector<std::pair<int, uint64_t>>& deferred) {
  granted.clear();
  deferred.clear();
  const int* first = requests.data();
  const int* end = first + requests.size();
  while (first != end) {
    const int group = *first / sharedBy_;
    const int* last = first;
    while (last != end && *last / sharedBy_ == group) ++last;
    arbitrateGroup(cycle, first, last, granted, deferred);
    first = last;
  }
}

void TriangleUnitArbiter::arbitrateGroup(uint64_t cycle, const int* first, const int* last,
                                         std::vector<int>& granted,
                                         std::vector<std::pair<int, uint64_t>>& deferred) {
  Unit& unit = units_[static_cast<size_t>(*first / sharedBy_)];
  const int* winner = nullptr;
  if (cycle >= unit.freeFrom) {
    winner = first;  // the lowest core, unless one at or after the priority asks
    for (const int* request = first; request != last; ++request)
      if (*request >= unit.priority) {
        winner = request;
        break;
      }
    granted.push_back(*winner);
    unit.freeFrom = cycle + interval_;
    const int groupFirst = *first / sharedBy_ * sharedBy_;
    const int next = *winner + 1;
    unit.priority = next < groupFirst + sharedBy_ && next < cores_ ? next : groupFirst;
  }
  for (const int* request = first; request != last; ++request)
    if (request != winner) deferred.emplace_back(*request, unit.freeFrom);
}

}  // namespace rtu
