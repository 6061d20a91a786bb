#pragma once
// The timed model of seed 001's ray pipe: the VGA reader's window on the frame buffer's SRAM (R1
// PERIPHERALS/vga.sv, simple_frame_buffer_handler.sv fbh_reader), which the pixel buffer's writer
// waits out (fbh_writer: pb_re = sram_re_b & ~pb_empty), as a closed form of the cycle so the lazy
// model can ask it in any cycle without stepping the counters.
//
// n cycles after reset, clk_25M (toggled every cycle from 0) has risen (n + 1) / 2 times, so the
// 25 MHz counters stand at k = (n + 1) / 2 mod 800 * 521: clk_cnt = k % 800, line_cnt = k / 800.
// fbh_active turns on after the cycles with vga_col = clk_cnt - 144 = 0x3ff (clk_cnt 143, 2K - 1
// and 2K for K = 800 line + 143) on a screen row (line 31 .. 510), off after those with vga_col =
// 638 (clk_cnt 782): active in cycles 2K .. 2K + 1277, an even count, so the one-hot register
// (0001 at reset, rotating every active cycle) has bit 0 or 2 set exactly in the active cycles of
// even n. The reader holds the SRAM then: n even, (n mod 833,600) / 2 = 800 line + c with
// c in 143 .. 781 and line in 31 .. 510. The whole pattern repeats every 833,600 cycles.

#include <cstdint>

namespace rtu {
namespace raypipe_timed {

class VgaWindow {
 public:
  static constexpr int64_t kScreen = 2 * 800 * 521;  // cycles in a screen: 833,600

  // phase: the cycles from reset to the run's cycle 0.
  explicit VgaWindow(int64_t phase) : phase_(phase % kScreen) {}

  // True when the VGA reader holds the SRAM in the run's cycle `cycle`.
  bool reading(int64_t cycle) const {
    const int64_t n = (phase_ + cycle) % kScreen;
    if (n % 2 != 0) return false;
    const int64_t column = (n / 2) % 800, line = (n / 2) / 800;
    return column >= 143 && column <= 781 && line >= 31 && line <= 510;
  }

 private:
  int64_t phase_ = 0;
};

}  // namespace raypipe_timed
}  // namespace rtu
