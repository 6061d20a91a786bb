// The buffer occupancy peak from changes decided out of cycle order (src/base/occupancy_peak.h).
// Expected peaks are counted by hand from the entries and exits listed in each case.

#include <catch2/catch.hpp>

#include "base/occupancy_peak.h"

using rtu::OccupancyPeak;

TEST_CASE("occupancy peak applies exits before entries within a cycle", "[occupancy]") {
  OccupancyPeak peak;
  peak.enter(3);
  peak.leave(5);
  peak.enter(5);  // the first leaves as the second enters: never two at once
  peak.leave(9);
  CHECK(peak.peak() == 1);
  peak.enter(7);  // decided later, for an earlier cycle: two from 7 to 9
  CHECK(peak.peak() == 2);
}

TEST_CASE("occupancy peak keeps changes far ahead and settles in cycle order", "[occupancy]") {
  OccupancyPeak peak;
  // 200 entries one cycle apart, each leaving 100 cycles later: 100 inside from cycle 100 on
  // (the exit at 100 + i and the entry at 100 + i meet in one cycle), decided in reverse order
  // so the calendar grows past its first size and wraps.
  for (int i = 199; i >= 0; --i) {
    peak.enter(static_cast<uint64_t>(i));
    peak.leave(static_cast<uint64_t>(i) + 100);
  }
  peak.settle(150);
  CHECK(peak.peak() == 100);
  // Changes at and after the settled cycle still count: 40 more entries in cycle 160.
  for (int i = 0; i < 40; ++i) peak.enter(160);
  CHECK(peak.peak() == 140);
  peak.settle(1000);
  for (int i = 0; i < 3; ++i) peak.enter(5000);  // far beyond everything settled
  CHECK(peak.peak() == 140);
}

TEST_CASE("occupancy peak settles only the cycles with changes, across words of marks",
          "[occupancy]") {
  OccupancyPeak peak;
  peak.enter(63);  // the last slot of the first word of marks
  peak.leave(64);  // the first of the next: one inside from 63 to 63
  peak.enter(64);  // inside from 64 to 129
  peak.leave(130);
  peak.enter(129);  // two inside in cycle 129 only
  peak.settle(60);
  peak.settle(64);  // applies cycle 63 alone
  peak.settle(65);
  CHECK(peak.peak() == 2);
  peak.settle(129);  // not yet cycle 129
  peak.enter(129);   // three in cycle 129 now
  peak.settle(100000);
  CHECK(peak.peak() == 3);
  // Far ahead of everything settled, after a long stretch of cycles without changes: two are
  // inside from 130 on, a third from 200000 to 200000.
  peak.enter(200000);
  peak.leave(200001);
  peak.settle(200001);
  CHECK(peak.peak() == 3);
  peak.enter(200001);  // two more in the cycle the third leaves: four inside
  peak.enter(200001);
  CHECK(peak.peak() == 4);
}
