// Resource bookings in cycle order and out of it (src/sim/memory/resource_booking.h), and the L2's
// out-of-order form against its cycle-order form (src/sim/memory/l2_cache_timing.h), cycles by
// hand.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "sim/memory/l2_cache_timing.h"
#include "sim/memory/resource_booking.h"

using namespace rtu;

TEST_CASE("Booking in cycle order: a request starts when the last one ended", "[booking]") {
  ResourceBooking bus(RequestOrder::Cycle);
  CHECK(bus.book(10, 4) == 10);  // [10, 14)
  CHECK(bus.book(11, 4) == 14);  // waits for the first: [14, 18)
  CHECK(bus.book(30, 2) == 30);  // idle bus: at once
  CHECK(bus.firstFree(31, 1) == 32);
}

TEST_CASE("Booking out of order: a request fills the first gap it fits in", "[booking]") {
  ResourceBooking bus(RequestOrder::Any);
  CHECK(bus.book(20, 4) == 20);  // [20, 24)
  CHECK(bus.book(10, 4) == 10);  // before it, free: [10, 14)
  CHECK(bus.book(12, 4) == 14);  // [14, 18): the gap 14..20 holds it
  CHECK(bus.book(15, 4) == 24);  // 18..20 is too short; after [20, 24)
  CHECK(bus.book(18, 2) == 18);  // exactly the gap 18..20
  CHECK(bus.firstFree(0, 10) == 0);
  CHECK(bus.firstFree(5, 10) == 28);  // [10, 28) is booked whole now
  bus.forgetBefore(25);               // nothing starts before 25 any more
  CHECK(bus.firstFree(0, 2) == 28);   // from 25 on: [24, 28) still stands
  CHECK(bus.book(25, 1) == 28);
  CHECK(bus.book(1000, 3) == 1000);  // far ahead: the ring grows and keeps what it held
  CHECK(bus.firstFree(26, 1) == 29);
}

TEST_CASE("Booking spread out of order: a request takes the first free cycles\\, gaps or not",
          "[booking]") {
  ResourceBooking bus(RequestOrder::Any);
  CHECK(bus.bookSpread(20, 4) == 24);  // [20, 24)
  CHECK(bus.bookSpread(26, 2) == 28);  // [26, 28)
  // From 17: 17, 18, 19, then past [20, 24): 24, 25, then past [26, 28): 28, 29, 30. Ends at 31.
  CHECK(bus.bookSpread(17, 8) == 31);
  CHECK(bus.firstFree(10, 1) == 10);
  CHECK(bus.firstFree(17, 1) == 31);       // 17 .. 30 all taken now
  CHECK(bus.bookSpread(40, 3) == 43);      // beyond every booking: consecutive
  CHECK(bus.bookSpread(5000, 2) == 5002);  // far ahead: the ring grows
  CHECK(bus.firstFree(41, 1) == 43);
}

TEST_CASE("Booking: both orders agree on requests that come in cycle order", "[booking]") {
  std::mt19937_64 random(5);
  ResourceBooking inOrder(RequestOrder::Cycle), anyOrder(RequestOrder::Any);
  ResourceBooking spreadInOrder(RequestOrder::Cycle), spreadAnyOrder(RequestOrder::Any);
  uint64_t from = 0;
  for (int i = 0; i < 2000; ++i) {
    from += random() % 7;
    const uint64_t cycles = 1 + random() % 5;
    REQUIRE(inOrder.book(from, cycles) == anyOrder.book(from, cycles));
    REQUIRE(spreadInOrder.bookSpread(from, cycles) == spreadAnyOrder.bookSpread(from, cycles));
  }
}

TEST_CASE("L2 out of order: equal to the cycle-order L2 on requests in cycle order", "[booking]") {
  CacheConfig cache = CacheConfig::l2();
  cache.sizeBytes = 4096;
  cache.maxOutstandingMisses = 2;
  const DramConfig dram;
  L2CacheTiming strict(cache, dram, RequestOrder::Cycle), loose(cache, dram, RequestOrder::Any);
  std::mt19937_64 random(9);
  uint64_t cycle = 0;
  for (int i = 0; i < 5000; ++i) {
    cycle += random() % 4;
    const uint64_t address = (random() % 256) * 64;
    loose.forgetBefore(cycle);  // as its users do: nothing comes for a cycle behind this one
    REQUIRE(strict.read(address, cycle) == loose.read(address, cycle));
  }
  CHECK(strict.stats().mshrQueueCycles == loose.stats().mshrQueueCycles);
  CHECK(strict.stats().portQueueCycles == loose.stats().portQueueCycles);
}

TEST_CASE("L2 out of order: an earlier request after a later one, cycles by hand", "[booking]") {
  CacheConfig cache = CacheConfig::l2();  // hit latency 8, 64-byte lines, 8 MSHRs
  DramConfig dram;                        // latency 40, 8 bytes a cycle: a line in 8 cycles
  L2CacheTiming strict(cache, dram, RequestOrder::Cycle), loose(cache, dram, RequestOrder::Any);
  // Line A at cycle 100: tag check to 108, DRAM from 148, line there at 156.
  CHECK(loose.read(0, 100) == 156);
  // Line B at cycle 50, after it: port free at 50, tag check to 58, DRAM bus free from 98 to
  // 106 (before A's transfer at 148), there at 106.
  CHECK(loose.read(64, 50) == 106);
  // Line C at cycle 95: tag check to 103, DRAM from 143: 143 .. 147 free, then past A's [148,
  // 156): 156, 157, 158. There at 159, not after A at 164 (the bus loses no cycle).
  CHECK(loose.read(128, 95) == 159);
  CHECK_THROWS_AS(strict.read(0, 100) + strict.read(64, 50), std::logic_error);
}
