#pragma once
// Booking of a resource that serves one request at a time, each for a number of cycles (the L2's
// request port, the DRAM data bus): a request that may start from cycle `from` is given the first
// run of free cycles long enough, at or after `from`.
//
// RequestOrder::Cycle, for the cycle-accurate model, whose requests come in cycle order: the
// resource is free from the end of the last booking on, so start = max(from, end of last).
// RequestOrder::Any, for the loosely-timed model, whose traversals run one after another and so
// make their requests out of cycle order: the booked cycles are kept, and a
// request fills the first gap it fits in, even one before a later booking. With requests in cycle
// order both give the same starts (a gap before the last booking is then always earlier than
// `from`). The booked cycles are a ring of bits from forgetBefore's cycle (no request starts
// before it) on, grown (a power of two long) when a booking lies further ahead: a few bit
// operations a request, where an ordered map of runs cost a tree node each.

#include <cstdint>
#include <vector>

namespace rtu {

enum class RequestOrder { Cycle, Any };

class ResourceBooking {
 public:
  explicit ResourceBooking(RequestOrder order = RequestOrder::Cycle) : order_(order) {}

  // Books `cycles` consecutive cycles, the first at or after `from`; returns the first. Inline
  // in cycle order: each of a cached run's L2 requests books the port.
  uint64_t book(uint64_t from, uint64_t cycles) {
    if (order_ != RequestOrder::Cycle) return bookAnyOrder(from, cycles);
    const uint64_t start = from > free_ ? from : free_;
    free_ = start + cycles;
    return start;
  }
  // Books the first `cycles` free cycles at or after `from`, consecutive or not; returns the cycle
  // after the last. In cycle order the same cycles as book(). In any order a request that comes
  // after later ones fills the gaps they left, however short: a transfer the resource would have
  // served first (it asked earlier) then takes the free cycles around them rather than waiting for
  // a gap as long as itself, so the resource loses no cycle to the order in which it heard its
  // requests (the DRAM data bus of the loosely-timed model, dram_channel.h).
  uint64_t bookSpread(uint64_t from, uint64_t cycles) {
    if (order_ == RequestOrder::Cycle) return book(from, cycles) + cycles;
    return bookSpreadAnyOrder(from, cycles);
  }
  // The first cycle that book() would return, without booking.
  uint64_t firstFree(uint64_t from, uint64_t cycles) const;
  // No later request starts before `cycle` (Any: drops the runs that end by then).
  void forgetBefore(uint64_t cycle);

 private:
  uint64_t bookAnyOrder(uint64_t from, uint64_t cycles);
  uint64_t bookSpreadAnyOrder(uint64_t from, uint64_t cycles);
  void mark(uint64_t cycle) { word(cycle) |= uint64_t{1} << (cycle % 64); }
  bool booked(uint64_t cycle) const;
  uint64_t& word(uint64_t cycle) { return bits_[(cycle & (ringCycles() - 1)) / 64]; }
  uint64_t ringCycles() const { return bits_.size() * 64; }
  void grow(uint64_t span);

  RequestOrder order_;
  uint64_t free_ = 0;  // Cycle: free from here on
  // Any: bit c mod ring size for cycle c in [base_, end_); none booked at or after end_.
  std::vector<uint64_t> bits_ = std::vector<uint64_t>(4, 0);
  uint64_t base_ = 0, end_ = 0;
};

}  // namespace rtu
