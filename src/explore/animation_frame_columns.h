#pragma once
// The columns every animation's per-frame statistics (animate's CSV) begin and end with, whichever
// way the frames are traced (the SVO scene manager's FrameStatistics, explore/animation_run.h; the
// two-level BVH's, kinds/bvh/explore/two_level_animation.h). F has frame, time, cycles,
// hostSeconds, clockMhz, frameMs() and framesPerSecond().

#include <string>

#include "base/statistics.h"

namespace rtu {

// A group of `title` holding the frame's number and time.
template <class F>
StatisticGroup<F> animationFrameColumns(const std::string& title) {
  StatisticGroup<F> group(title);
  group.setting(Statistic("frame", "", "the frame's number"), &F::frame)
      .setting(Statistic("time_s", "s", "the frame's time in the animation"), &F::time);
  return group;
}

// `group` with the frame's cycles, time and rate at the clock, and the host's time, appended.
template <class F>
StatisticGroup<F>& withFrameTime(StatisticGroup<F>& group) {
  return group
      .count(Statistic("cycles", "cycles",
                       "the frame's total on the RTU (recurrence or simulated)"),
             &F::cycles)
      .derived(Statistic("frame_ms", "ms", "the frame's time at the clock"), &F::frameMs)
      .derived(Statistic("fps", "frames/s", "frames per second at the clock"), &F::framesPerSecond)
      .real(Statistic("host_s", "s", "host time the frame took"), &F::hostSeconds)
      .setting(Statistic("clock_mhz", "MHz", "the clock of frame_ms and fps").notAColumn(),
               &F::clockMhz);
}

}  // namespace rtu
