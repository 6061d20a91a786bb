#pragma once
// The per-cycle reference of seed 001's ray pipe: the VGA reader's window on the frame buffer's
// SRAM (R1 PERIPHERALS/simple_frame_buffer_handler.sv fbh_reader, PERIPHERALS/vga.sv,
// COMMON/defines.sv), which the pixel buffer's writer must wait out (fbh_writer: pb_re =
// sram_re_b & ~pb_empty).
//
// vga.sv: clk_25M toggles every 50 MHz cycle from 0 at reset; on its rising edge (after the 1st,
// 3rd, ... 50 MHz edge) clk_cnt counts 0 .. 799 (HS_TS = 144 + 640 + 16) and line_cnt 0 .. 520
// (VS_TS = 31 + 480 + 10); vga_col = clk_cnt - 144, vga_row = line_cnt - 31, in 10 bits.
// fbh_reader: fbh_active turns on after a cycle with vga_col = 0x3ff on a screen row (0 .. 479)
// and off after one with vga_col = 638; while active a 4-bit one-hot register (0001 at reset)
// rotates every cycle and the SRAM is read when its bit 0 or bit 2 is set: every other active
// cycle, 639 reads in each screen row's 1278 active cycles.

#include <cstdint>

namespace rtu {
namespace raypipe_ref {

class VgaReader {
 public:
  static constexpr int kHsTotal = 800, kHsOffset = 144, kVsTotal = 521, kVsOffset = 31;
  static constexpr int kRows = 480;
  static constexpr int64_t kScreenCycles = 2 * kHsTotal * kVsTotal;  // 833,600

  // True when the reader holds the SRAM this cycle (sram_re_b low).
  bool reading() const { return active_ && (shift_ & 0x5) != 0; }

  // The edge ending this cycle.
  void tick() {
    const int col = (clkCount_ - kHsOffset) & 0x3ff, row = (lineCount_ - kVsOffset) & 0x3ff;
    const bool on = col == 0x3ff && row < kRows, off = col == 638;
    if (active_) shift_ = static_cast<uint8_t>(((shift_ & 1) << 3) | (shift_ >> 1));
    if (on || off) active_ = on;
    clk25_ = !clk25_;
    if (clk25_) {  // clk_25M's rising edge: the counters
      const bool incLine = clkCount_ == kHsTotal - 1;
      const bool clearLine = incLine && lineCount_ == kVsTotal - 1;
      clkCount_ = incLine ? 0 : clkCount_ + 1;
      lineCount_ = clearLine ? 0 : (incLine ? lineCount_ + 1 : lineCount_);
    }
  }

 private:
  bool clk25_ = false, active_ = false;
  int clkCount_ = 0, lineCount_ = 0;
  uint8_t shift_ = 1;
};

}  // namespace raypipe_ref
}  // namespace rtu
