#pragma once
// Seed 001's primary ray generator (PRG: R1 PRG/primary_ray_generator.sv and prg_pl.sv; S1
// §2.6.2; specs/001 §2.2 "Primary ray generator"): which pixel's ray it issues when, and the ray.
//
// Order. At the seed's six levels (20x15 ... 640x480) the frame is cut into 20x15 blocks issued in
// the Z (Morton) order of a 10-bit block counter: its even bits are the block's column, its odd
// bits its row from the top. Inside a block x runs fastest and the rows go top first. Any other
// size that 20x15 blocks tile takes the same order with the counter's codes outside the block
// grid skipped; a size they do not tile is issued row by row from the top (one block the size of
// the frame).
//
// Pixels. x counts columns from the left and y rows from the top (rtusim's image coordinates);
// the RTL's y counts from the bottom, y_prg = rows - 1 - y, so its pixelID, (rows - 1 - y_prg)
// cols + x, is y cols + x here: rtusim's pixel index.
//
// Rays. origin = E; direction = U (x pw - 320) + V (y_prg pw - 240) + 240 W, unnormalised, at the
// pixel's lower-left corner (no half-pixel offset), pw = 32, 16, 8, 4, 2, 1 for levels 0-5, in
// the RTL's binary32 order (kinds/kd/binary32.h: flush-to-zero, RNE): u = float(x) pw + -320,
// v = float(y_prg) pw + -240, d_c = (u U_c + v V_c) + W_c 240. Any other size keeps the vertical
// field (90 degrees for unit U, V, W) and square pixels: pw = 480 / rows and -320 becomes
// -cols pw / 2, each rounded to binary32 (both exact at the seed's levels).

#include <cstdint>
#include <vector>

#include "kinds/kd/kd_units.h"
#include "raypipe/raypipe_config.h"

namespace rtu {

constexpr int kPrgLevels = 6;  // 20x15 (level 0) ... 640x480 (level 5)
constexpr int kPrgBlockWidth = 20, kPrgBlockHeight = 15;

struct PrgFrameSize {
  int width = 640, height = 480;
};

// The seed's level 0-5: 20 * 2^level by 15 * 2^level. Throws std::invalid_argument naming
// raypipe.level outside 0-5.
PrgFrameSize prgLevelSize(int level);

struct PrgPixel {
  uint32_t pixelId = 0;  // the shader's pixel number, y * width + x
  int x = 0, y = 0;      // column from the left, row from the top
};

// Every pixel of the frame in the order the PRG issues them. Throws std::invalid_argument for a
// size below 1x1.
std::vector<PrgPixel> prgIssueOrder(PrgFrameSize size);

// The PRG's ray for pixel (x, y) of a frame of `size` (hardware space).
KdRay prgRay(const RaypipeCamera& camera, PrgFrameSize size, int x, int y);

struct PrimaryRay {
  PrgPixel pixel;
  KdRay ray;
};

// The frame's rays in issue order.
std::vector<PrimaryRay> primaryRays(const RaypipeCamera& camera, PrgFrameSize size);

}  // namespace rtu
