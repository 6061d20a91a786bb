#pragma once
// What a run of seed 001's ray pipe takes besides the configuration and gives back (issue 29): the
// per-cycle reference (reference/raypipe_cycles.h) and the timed model (sim/raypipe/) share these,
// so a run of one compares with a run of the other field by field.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "kinds/kd/kd_traversal.h"
#include "kinds/kd/kd_units.h"
#include "raypipe/raypipe_cache.h"

namespace rtu {

// The SRAM writer behind the pixel buffer (R1 PERIPHERALS/simple_frame_buffer_handler.sv
// fbh_writer: pb_re = sram_re_b & ~pb_empty). By default it takes one pixel every cycle the buffer
// is not empty; with the VGA read window (raypipe_vga.h) it waits out the cycles the VGA reader
// holds the SRAM: every other cycle of each screen row's active part. vgaPhase: the 50 MHz
// cycles from reset to cycle 0 (the VGA counters start at reset; R1 does not tie a frame's start
// to the screen's). In the RTL recordings (tests/data/raypipe_rtl/README.md) it is "start (abs)"
// + 1, and with it both models give every recorded exit cycle (docs/raypipe.md, "Against the
// RTL").
struct RaypipePixelWriter {
  bool vgaReadWindow = false;
  int64_t vgaPhase = 0;
};

// What runRaypipeCycles does besides the frame.
struct RaypipeCycleOptions {
  RaypipePixelWriter writer;
  bool recordTransfers = false;  // fill RaypipeCycleRun::transfers
  // Cycles from reset to cycle 0: the shader writes ray id i into its FIFO i cycles after reset and
  // blocks results for the first 512 (is_init). By default long past: every id shown at cycle 0.
  int64_t cyclesSinceReset = 1000000;
};

// A unit taking an item in a cycle (as RaypipeUnitActivity counts it; an arbiter's grant into its
// output FIFO), for cycle-by-cycle comparison with a timed model.
struct RaypipeTransfer {
  int64_t cycle = 0;
  const char* unit = "";  // RaypipeUnitActivity::unit's names
  uint32_t rayId = 0;     // kNoRayId before the shader gives one (the PRG)
  uint32_t index = 0;     // the pixel's place in the PRG's order
  static constexpr uint32_t kNoRayId = 0xffffffffu;
};

struct RaypipeCycleRay {
  KdRay ray;
  uint32_t pixelId = 0;
};

// One ray's outcome: the golden traversal's result fields, and when it left.
struct RaypipeCycleResult {
  uint32_t pixelId = 0;
  bool hit = false, boxMiss = false;
  float t = 0, u = 0, v = 0;   // 0 on a miss, as KdResult
  uint32_t primitive = 0;      // the hit triangle's id; 0 on a miss
  KdRayCounts counts;          // as the golden traversal counts them
  int64_t issueCycle = -1;     // the PRG accepted the pixel (x_y_valid)
  int64_t shaderInCycle = -1;  // the shader gave it a ray id (into SINT)
  int64_t exitCycle = -1;      // it left the shader into the pixel buffer (pb_we)
  uint32_t rayId = 0;
};

// The pipe's units as the models count their activity and name them in transfer records: one
// vocabulary, so that a run of the reference and one of the timed model compare name by name.
enum class RaypipeUnit {
  Prg,
  Sint,
  Tarb,
  Tcache,
  Trav,
  TravMath,
  TravDecide,
  StackRead,
  RestartRead,
  Larb,
  Lcache,
  Icache,
  Int,
  List,
  ShaderArb,
  ShaderReturn,
  PixelWriter,
  kCount
};

inline const char* raypipeUnitName(RaypipeUnit u) {
  static const char* names[] = {
      "prg",         "sint",     "tarb",       "tcache",        "trav",        "trav_math",
      "trav_decide", "ss_stack", "ss_restart", "larb",          "lcache",      "icache",
      "int",         "list",     "shader_arb", "shader_return", "pixel_writer"};
  return names[static_cast<size_t>(u)];
}

struct RaypipeUnitActivity {
  std::string unit;
  int64_t busy = 0;   // cycles the unit accepted an item
  int64_t stall = 0;  // cycles an item was offered to it and stalled
};

struct RaypipeFifoPeak {
  std::string fifo;
  int depth = 0;
  int peak = 0;
};

struct RaypipeCycleRun {
  std::vector<RaypipeCycleResult> results;  // in input order
  int64_t lastExitCycle = -1;               // the cycle the last pixel left the shader
  int64_t frameCycles = 0;                  // lastExitCycle + 1: cycles 0 .. lastExitCycle
  int64_t lastWriteCycle = -1;              // the SRAM writer took the last pixel
  int64_t writerWaits = 0;                  // cycles a pixel waited for the VGA reader
  std::vector<RaypipeUnitActivity> units;
  std::vector<RaypipeFifoPeak> fifos;
  int maxRaysInFlight = 0;    // ray ids held at once, at most RaypipeConfig::raysInFlight
  int64_t staleListHits = 0;  // rays that ended as a miss with a hit kept in the list record
  // With raypipe.cache = set_associative: each cache's counts (tcache, then tcache_1 with two
  // traversal units, lcache, icache) and the DRAM's; else none.
  std::vector<RaypipeCacheCounts> caches;
  RaypipeDramCounts dram;
  std::vector<RaypipeTransfer> transfers;  // in cycle order, when recorded
  double hostSeconds = 0;

  // Takes the results and derives the frame's end from them: the last exit and the cycles up to
  // it (the one definition both models give).
  void setResults(std::vector<RaypipeCycleResult> frameResults) {
    results = std::move(frameResults);
    for (const RaypipeCycleResult& r : results)
      lastExitCycle = std::max(lastExitCycle, r.exitCycle);
    frameCycles = lastExitCycle + 1;
  }
};

}  // namespace rtu
