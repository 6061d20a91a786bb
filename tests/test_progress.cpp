// The progress line of fps, sweep and animate (src/explore/sweep_workers.h): its ETA follows the
// share of the work done, not of the rows (fps rows grow with the resolution).

#include <catch2/catch.hpp>

#include "explore/sweep_workers.h"

using namespace rtu;

TEST_CASE("Progress: the ETA follows the work done, not the rows done", "[progress]") {
  // Rows of 320x180 and 1920x1080 rays: the small one done in 10 s is 57,600 of 2,131,200 rays,
  // 1/37 of the work, so 36 times as much is left: 6 minutes, where one row of two said 10 s.
  const double smallRowDone = 57600.0 / (57600.0 + 2073600.0);
  CHECK(progressText("fps", 1, 2, "rows", 0, 10.0, smallRowDone) ==
        "fps 1/2 rows, 0:00:10 elapsed, ETA 0:06:00");
  CHECK(progressText("sweep", 3, 4, "rows", 1, 30.0, 0.75) ==
        "sweep 3/4 rows, 1 failed, 0:00:30 elapsed, ETA 0:00:10");
  // Nothing done yet, or everything: no ETA.
  CHECK(progressText("fps", 0, 2, "rows", 0, 1.0, 0.0) == "fps 0/2 rows, 0:00:01 elapsed");
  CHECK(progressText("fps", 2, 2, "rows", 0, 370.0, 1.0) == "fps 2/2 rows, 0:06:10 elapsed");
}
