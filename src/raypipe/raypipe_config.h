#pragma once
// The settings of seed 001's ray pipe (the Tray Racer, issue 29): the final build the seed
// demonstrated (R1 DEMOS/t5.sv with RAYTRACER/raypipe_simple_caches.sv: one traversal unit,
// block-RAM "caches", the simple shader, 50 MHz) as the defaults, each as specs/001 §2.2 and §9.2
// give it from the RTL. Plain data and its checks, no SystemC (the untimed half, the per-cycle
// reference and the timed model all read it).

#include <array>
#include <cstdint>

#include "kinds/kd/binary32.h"
#include "kinds/kd/kd_units.h"

namespace rtu {

// What stands in front of the scene memory: the block RAMs as built (full capacity, a 2-cycle
// read, never a miss), or the designed 2-way set-associative caches in front of DRAM.
enum class RaypipeCacheKind : uint8_t { BlockRam, SetAssociative };

// The seed's camera as its registers hold it: eye E and basis U, V, W in hardware space; the
// primary ray generator computes unnormalised directions U (x pw - 320) + V (y pw - 240) + 240 W.
struct RaypipeCamera {
  std::array<float, 3> eye{1.125f, 1.125f, -1.25f};  // R1 INIT_CAM (SYNTH build)
  std::array<float, 3> u{1, 0, 0}, v{0, 1, 0}, w{0, 0, 1};
};

// Fixed-latency units: cycles from accepting an item to its result, and the cycles between
// accepted items (1 = one per cycle).
struct RaypipeLatencies {
  int prg = 41, prgInterval = 3;    // primary ray generator (pipe_valid_stall DEPTH 41, v0)
  int sint = 18, sintInterval = 3;  // scene-box intersection (DEPTH 18, 1/3 rate)
  int travMath = 14;                // TRAV: split - o (add 7), / d (div 6), registered
  int intersection = 45;            // INT: the unit-triangle test, one triangle a cycle
  int memoryRead = 2;               // block RAM caches and raystores
};

struct RaypipeFifoDepths {
  int prg = 16;        // PRG -> shader (16x211 BRAM FIFO)
  int sint = 18;       // each of SINT's three outputs
  int tarb = 512;      // traversal arbiter's output
  int larb = 512;      // list arbiter's output
  int travLeaf = 8;    // TRAV's leaf FIFO
  int travMath = 15;   // beside TRAV's math pipe
  int intList = 256;   // INT -> list unit
  int intLarb = 256;   // INT -> list arbiter (next triangle)
  int intShader = 46;  // INT -> shader (shadow hits)
  int memoryOut = 3;   // after each cache and raystore read
  int pixelBuffer = 20;
};

// The designed caches in front of DRAM (cache = SetAssociative; R1 RAYTRACER/caches/cache.sv and
// COMMON/defines.sv, docs/raypipe.md "The set-associative caches"): 2 ways of `lines` lines each
// (the RTL's NUM_LINES, a power of two), a line's width fixed by what it holds; behind them
// rtusim's DRAM channel (sim/memory/dram_channel.h) through R1's memory request arbiter.
struct RaypipeCacheSettings {
  int tcacheLines = 512;         // T_NUM_LINES: 8 nodes (384 bits) a line
  int lcacheLines = 1024;        // L_NUM_LINES: 16 list entries (256 bits) a line
  int icacheLines = 1024;        // I_NUM_LINES: one triangle's matrix (288 bits) a line
  int dramLatency = 8;           // cycles from the arbiter's read to the first word (an estimate)
  double dramBytesPerCycle = 4;  // the 32-bit SDRAM at the pipe's clock
};

struct RaypipeConfig {
  int traversalUnits = 1;
  int shortStackDepth = 4;  // S1 §2.6.9: "the 4-deep stack"
  int raysInFlight = 512;   // the shader's ray ids (S1 §2.6.11: "only 512")
  RaypipeLatencies latency;
  RaypipeFifoDepths fifo;
  RaypipeCacheKind cache = RaypipeCacheKind::BlockRam;
  RaypipeCacheSettings caches;          // used with cache = SetAssociative
  Division division = Division::Altfp;  // as built: the shipped altfp_div (altfp_div.h)
  KdTMaxClamp tMaxClamp = KdTMaxClamp::AsBuilt;
  double clockMHz = 50.0;  // R1 COMMON/defines.sv CLK_FREQ
  // The pixel buffer's SRAM writer waits out the VGA reader's window, as built (docs/raypipe.md,
  // "Against the RTL": with it the models give the RTL's exit cycles where the buffer fills);
  // vgaPhase: the 50 MHz cycles from reset to the frame's cycle 0, which place the screen.
  bool vgaWindow = true;
  int64_t vgaPhase = 0;

  // Throws std::invalid_argument naming the setting for a value the pipe cannot take (counts and
  // depths below 1, ray ids beyond the 9-bit rayID's 512, a stack deeper than its 3-bit count, a
  // cache's lines not a power of two, a DRAM without bandwidth).
  void validate() const;
};

}  // namespace rtu
