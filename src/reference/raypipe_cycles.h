#pragma once
// The per-cycle reference of seed 001's ray pipe (the Tray Racer, issue 29 §3): the final build R1
// demonstrated (DEMOS/t5.sv with RAYTRACER/raypipe_simple_caches.sv), every unit stepped once a
// cycle with the RTL's valid/stall handshake, written from the RTL apart from any timed model, as
// rtl_cycle_model is for the thesis RTU. docs/raypipe.md, "Timing rules (the per-cycle
// reference)", gives the rules unit by unit with their R1 files, and what is not modelled yet.
//
// The arithmetic and the traversal's decisions are kinds/kd's (kd_units.h over the memory image of
// kd_image.h, read as kd_traversal.h reads it), so each ray's result is bit-exact with the golden
// traversal; the control (short stack, restart, list unit, routing) is transcribed here from the
// RTL. Input: the primary rays in the PRG's issue order with their pixel ids (the PRG's values and
// pixel order are raypipe/'s); the PRG's timing is modelled here.
//
// Cycle 0 is the first cycle the PRG is active (a v0 cycle of the shared modulo-3 phase: v0 when
// cycle % 3 == 0, v1 at 1, v2 at 2, as t5.sv's counter). By default the shader's ray-id FIFO is
// full at cycle 0 (reset long past; RaypipeCycleOptions::cyclesSinceReset models the fill).

#include <cstdint>
#include <string>
#include <vector>

#include "kinds/kd/kd_image.h"
#include "kinds/kd/kd_traversal.h"
#include "raypipe/raypipe_config.h"

namespace rtu {

// The SRAM writer behind the pixel buffer (R1 PERIPHERALS/simple_frame_buffer_handler.sv
// fbh_writer: pb_re = sram_re_b & ~pb_empty). By default it takes one pixel every cycle the buffer
// is not empty; with the VGA read window (raypipe_vga.h) it waits out the cycles the VGA reader
// holds the SRAM: every other cycle of each screen row's active part. vgaPhase: the 50 MHz
// cycles from reset to cycle 0 (the VGA counters start at reset; R1 does not tie a frame's start
// to the screen's).
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
  std::vector<RaypipeTransfer> transfers;  // in cycle order, when recorded
  double hostSeconds = 0;
};

// Runs one frame. Throws std::invalid_argument for a configuration the reference does not take
// (more than one traversal unit, the set-associative caches, a negative VGA phase), logic_error
// when the pipe breaks one of its own rules (a write to a full FIFO, a ray id used twice, a hazard
// on a ray's stack or restart record, no progress for a million cycles).
RaypipeCycleRun runRaypipeCycles(const RaypipeConfig& config, const KdImage& image,
                                 const std::vector<RaypipeCycleRay>& rays,
                                 const RaypipeCycleOptions& options = {});

}  // namespace rtu
