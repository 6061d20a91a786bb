#pragma once
// Booking of a resource that serves one request at a time, each for a number of cycles (the L2's
// request port, the DRAM data bus): a request that may start from cycle `from` is given the first
// run of free cycles long enough, at or after `from`.
//
// RequestOrder::Cycle, for the cycle-accurate model, whose requests come in cycle order: the
// resource is free from the end of the last booking on, so start = max(from, end of last).
// RequestOrder::Any, for the loosely-timed model, whose cores run ahead of each other within a
// quantum and so make their requests out of cycle order: the booked runs are kept, and a request
// fills the first gap it fits in, even one before a later booking. With requests in cycle order
// both give the same starts (a gap before the last booking is then always earlier than `from`).
// Runs that end before forgetBefore's cycle are dropped: no request can start before it.

#include <cstdint>
#include <map>

namespace rtu {

enum class RequestOrder { Cycle, Any };

class ResourceBooking {
 public:
  explicit ResourceBooking(RequestOrder order = RequestOrder::Cycle) : order_(order) {}

  // Books `cycles` consecutive cycles, the first at or after `from`; returns the first.
  uint64_t book(uint64_t from, uint64_t cycles);
  // The first cycle that book() would return, without booking.
  uint64_t firstFree(uint64_t from, uint64_t cycles) const;
  // No later request starts before `cycle` (Any: drops the runs that end by then).
  void forgetBefore(uint64_t cycle);

 private:
  void insertRun(uint64_t start, uint64_t end);

  RequestOrder order_;
  uint64_t free_ = 0;                  // Cycle: free from here on
  std::map<uint64_t, uint64_t> busy_;  // Any: booked runs, start -> end (exclusive), disjoint
};

}  // namespace rtu
