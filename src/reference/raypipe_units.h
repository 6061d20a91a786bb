#pragma once
// The per-cycle reference of seed 001's ray pipe: the units' state (raypipe_cycles.cpp steps it).
// Every channel carries a Flit, the union of the RTL's packed structs (tarb_t, leaf_info_t,
// trav_to_ss_t, int_to_list_t, ...); a ray's data that the RTL keeps in BRAMs indexed by the ray
// id (the raystores, the short stack's four slot RAMs and restart RAM, the list unit's t_cur,
// int_info and leaf_max RAMs, the shader's pixel ids) is its Slot.
//
// Depths and latencies come from RaypipeConfig where it has them; the units' small internal FIFOs
// and pipes are R1's constants (docs/raypipe.md, "Timing rules (the per-cycle reference)"):
//   shader (simple_shade_unit.sv): arbiter FIFO 2, VS pipe 2, ray-data FIFO 3
//   shortstack.sv: request and write FIFOs 3, stack VS pipe 2 and FIFO 3, restart VS pipe 3,
//                  miss and not-miss FIFOs 4
//   list_unit.sv: VS pipe 4, last FIFO 5, hit VS pipe 2, hit FIFO 3

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "kinds/kd/kd_traversal.h"
#include "raypipe/raypipe_config.h"
#include "reference/raypipe_arbiter.h"
#include "reference/raypipe_cache.h"
#include "reference/raypipe_cycles.h"
#include "reference/raypipe_fifo.h"
#include "reference/raypipe_flit.h"
#include "reference/raypipe_pipe.h"

namespace rtu {
namespace raypipe_ref {

struct StackEntry {
  uint32_t node = 0;
  float tMax = 0;
};

// What the RTL's BRAMs hold of one ray id, and the reference's hazard checks on them.
struct Slot {
  bool busy = false;
  uint32_t index = 0;  // the shader's pixel-id BRAM
  KdRay ray;           // the raystores
  std::vector<StackEntry> stack;
  uint32_t restNode = 0;
  float tMaxScene = 0;
  bool restWritten = false;
  int pendingStackWrites = 0, pendingRestWrites = 0;
  bool hitCur = false;  // the list unit's t_cur and int_info
  float tCur = 0, uCur = 0, vCur = 0;
  uint32_t triCur = 0;
  float leafMax = 0;
  KdRayCounts counts;
};

using Unit = RaypipeUnit;

inline const char* unitName(Unit u) { return raypipeUnitName(u); }

class Activity {
 public:
  void busy(Unit u) {
    ++busy_[static_cast<size_t>(u)];
    ++total_;
  }
  void stall(Unit u) { ++stall_[static_cast<size_t>(u)]; }
  int64_t total() const { return total_; }
  std::vector<RaypipeUnitActivity> table() const {
    std::vector<RaypipeUnitActivity> rows;
    for (size_t i = 0; i < static_cast<size_t>(Unit::kCount); ++i)
      rows.push_back(RaypipeUnitActivity{unitName(static_cast<Unit>(i)), busy_[i], stall_[i]});
    return rows;
  }

 private:
  std::array<int64_t, static_cast<size_t>(Unit::kCount)> busy_{}, stall_{};
  int64_t total_ = 0;
};

// A block-RAM read (R1 RAYTRACER/caches/simple_cache.sv, raystore/raystore_simple.sv): a
// pipe_valid_stall of the read latency, then a 3-entry register FIFO; us_stall = ds_stall &
// (items in the pipe >= the FIFO's free slots).
struct MemoryRead {
  MemoryRead(const std::string& name, int latency, int depth) : pipe(latency), fifo(name, depth) {}
  bool usStall(bool dsStall) const { return pipe.usStall(dsStall, fifo.numLeft()); }
  void tick(int64_t now) {
    pipe.tick(now);
    fifo.tick(now);
  }
  PipeValidStall<Flit> pipe;
  RegFifo<Flit> fifo;
};

// The shortstack's read arbitration over its three request FIFOs (trav0, trav1, list): the first
// valid in the order p, p+1, p+2; p advances every cycle any is valid.
struct RoundRobin3 {
  template <class Valid>
  int choose(Valid valid) {
    int chosen = -1;
    bool any = false;
    for (int k = 0; k < 3; ++k) {
      const int i = (pointer + k) % 3;
      if (valid(i)) {
        any = true;
        if (chosen < 0) chosen = i;
      }
    }
    if (any) pointer = (pointer + 1) % 3;
    return chosen;
  }
  int pointer = 0;
};

// One traversal unit with its tcache and raystore #0 (trav_unit.sv; raypipe_2trav.sv gives each of
// its two units their own, and a stack write FIFO in the shortstack): unit 0's FIFOs keep the
// one-unit build's names, unit i's add _i.
struct TravUnit {
  TravUnit(const RaypipeConfig& c, int i);
  CacheRead tcache;
  MemoryRead rs0;
  RegFifo<Flit> leafFifo;
  PipeValidStall<Flit> travPipe;
  RegFifo<Flit> travFifo;
  RegFifo<Flit> stackWrite;
  // the registered outputs to the shortstack, tarb, larb and the list unit's leaf_max
  bool ssValid = false, tarbValid = false, larbValid = false, listValid = false;
  bool ssValidNext = false, tarbValidNext = false, larbValidNext = false, listValidNext = false;
  Flit ss, tarbOut, larbOut, list;
  Flit ssNext, tarbOutNext, larbOutNext, listNext;
  void keepRegisters();
  void tick(int64_t now);
};

struct Units {
  explicit Units(const RaypipeConfig& c);

  // PRG (primary_ray_generator.sv): the 41-deep pipe, the 16-deep BRAM FIFO to the shader
  PipeValidStall<Flit> prgPipe;
  ShowAheadFifo<Flit> prgFifo;
  // the shader's ray-id FIFO (512 x 9 BRAM)
  ShowAheadFifo<uint32_t> idFifo;
  // SINT
  PipeValidStall<Flit> sintPipe;
  RegFifo<Flit> sintTarb, sintSs, sintShader;
  // tarb: [0] stack pop, [1] restart, [2 + i] traversal unit i, [2 + units] SINT; output i to unit
  // i's tcache
  RotatingArbiter<Flit, 5, ShowAheadFifo<Flit>> tarb;
  std::vector<TravUnit> trav;  // raypipe.traversal_units
  // shortstack: request FIFOs [trav0, trav1, list] and restart writes [trav0, trav1, SINT]
  std::vector<RegFifo<Flit>> stackRead, restRead, restWrite;
  PipeValidStall<Flit> stackPipe, restPipe;
  RegFifo<Flit> stackFifo, notMissFifo, missFifo;
  RoundRobin3 stackReadChoice, restReadChoice;
  int restWritePointer = 0, stackWritePointer = 0;
  // larb: [i] traversal unit i's leaf, [units] INT's next triangle; lcache, icache, raystore #1,
  // INT
  RotatingArbiter<Flit, 3, ShowAheadFifo<Flit>> larb;
  CacheRead lcache, icache;
  MemoryRead rs1;
  PipeValidStall<Flit> intPipe;
  ShowAheadFifo<Flit> intList, intLarb;
  int intShaderNumLeft;  // the shadow-hit FIFO, never written by primary rays
  // the list unit and raystore #2
  PipeValidStall<Flit> listPipe;
  RegFifo<Flit> listLast;
  PipeValidStall<Flit> listHitPipe;
  RegFifo<Flit> listHitFifo;
  bool toSsValid = false, toSsValidNext = false;
  Flit toSs, toSsNext;
  MemoryRead rs2;
  // the shader's return side and the pixel buffer
  RotatingArbiter<Flit, 4, RegFifo<Flit>> shaderArb;
  PipeValidStall<Flit> shaderPipe;
  RegFifo<Flit> shaderData;
  RegFifo<Flit> pixelBuffer;
  // the memory request arbiter behind the caches (set_associative)
  DramArbiter dram;

  // The arbiters' offers of the cycle, and the registers' next values as their current ones.
  void offerAll(int64_t now);
  // The shortstack's input stalls (combinational in the request and the FIFOs' full flags).
  bool travToSsStall(size_t i) const;
  bool listToSsStall() const;
  void tick(int64_t now);
  std::vector<RaypipeFifoPeak> fifoPeaks() const;
  std::vector<RaypipeCacheCounts> cacheCounts() const;
};

}  // namespace raypipe_ref
}  // namespace rtu
