// The ring queue (base/ring_queue.h): first in, first out across its ring's wrap and growth.
#include <catch2/catch.hpp>

#include <deque>

#include "base/ring_queue.h"

namespace rtu {

TEST_CASE("Ring queue: elements leave in the order they came\\, across wraps and growth",
          "[ring_queue]") {
  RingQueue<int> queue;
  std::deque<int> expected;  // the standard queue as the reference
  int next = 0;
  // Pushes and pops interleaved so the head wraps around the ring several times before and after
  // each growth (4, 8 and 16 slots).
  for (int round = 0; round < 40; ++round) {
    const int pushes = 1 + round % 5, pops = round % 4;
    for (int i = 0; i < pushes; ++i) {
      queue.push_back(int{next});
      expected.push_back(next++);
    }
    REQUIRE(queue.back() == expected.back());
    for (int i = 0; i < pops && !expected.empty(); ++i) {
      REQUIRE(queue.front() == expected.front());
      queue.pop_front();
      expected.pop_front();
    }
    REQUIRE(queue.size() == expected.size());
    for (size_t i = 0; i < expected.size(); ++i) REQUIRE(queue[i] == expected[i]);
  }
  while (!expected.empty()) {
    REQUIRE(queue.front() == expected.front());
    queue.pop_front();
    expected.pop_front();
  }
  CHECK(queue.empty());
}

}  // namespace rtu
