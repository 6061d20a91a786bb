#pragma once
// The timed model of seed 001's ray pipe: its channels and per-unit counters (timed_pipe.h steps
// them). Depths and latencies come from RaypipeConfig where it has them; the units' small internal
// FIFOs and pipes are R1's constants (docs/raypipe.md, "Timing rules"): the shader's arbiter FIFO
// 2, VS pipe 2 and ray-data FIFO 3; the shortstack's request and write FIFOs 3, stack pipe 2 and
// FIFO 3, restart pipe 3, miss and not-miss FIFOs 4; the list unit's pipe 4, last FIFO 5, hit
// pipe 2 and hit FIFO 3.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "raypipe/raypipe_config.h"
#include "raypipe/raypipe_run.h"
#include "sim/raypipe/dram_arbiter.h"
#include "sim/raypipe/latency_pipe.h"
#include "sim/raypipe/memory_read.h"
#include "sim/raypipe/ray_token.h"
#include "sim/raypipe/rotating_arbiter.h"
#include "sim/raypipe/staged_register.h"
#include "sim/raypipe/timed_cache.h"
#include "sim/raypipe/timed_queue.h"

namespace rtu {
namespace raypipe_timed {

using Unit = RaypipeUnit;
inline const char* unitName(Unit u) { return raypipeUnitName(u); }

using Fifo = TimedQueue<RayToken>;
using Register = StagedRegister<RayToken>;

// One traversal unit with its tcache and raystore #0 (trav_unit.sv; raypipe_2trav.sv gives each
// of its two units their own): unit 0's FIFOs keep the one-unit build's names, unit i's add _i.
struct TravUnit {
  TravUnit(const RaypipeConfig& c, int i, DramArbiter& dram);
  TimedCache tcache;
  MemoryRead rs0;
  Fifo leafFifo;
  LatencyPipe<RayToken> travPipe;
  Fifo travFifo;
  Register travSs, travTarb, travLarb, travList;
};

struct Channels {
  explicit Channels(const RaypipeConfig& c);
  // Every FIFO of ray tokens, in the pipe's order (the shader's ray-id FIFO is idFifo).
  std::vector<Fifo*> fifos();
  std::vector<RaypipeFifoPeak> peaks();
  std::vector<RaypipeCacheCounts> cacheCounts() const;

  DramArbiter dram;  // behind the caches (set_associative); first, as they refer to it

  LatencyPipe<RayToken> prgPipe;
  Fifo prgFifo;
  TimedQueue<uint32_t> idFifo;
  LatencyPipe<RayToken> sintPipe;
  Fifo sintTarb, sintSs, sintShader;
  // tarb: [0] stack pop, [1] restart, [2 + i] traversal unit i, [2 + units] SINT; output i to
  // unit i's tcache
  RotatingArbiter<RayToken> tarb;
  std::vector<TravUnit> trav;                          // raypipe.traversal_units
  std::array<Fifo, 3> stackRead, restRead, restWrite;  // [trav0, trav1, list or SINT]
  std::vector<Fifo> stackWrite;                        // one per traversal unit
  LatencyPipe<RayToken> stackPipe, restPipe;
  Fifo stackFifo, notMissFifo, missFifo;
  int stackReadPointer = 0, restReadPointer = 0, restWritePointer = 0, stackWritePointer = 0;
  RotatingArbiter<RayToken> larb;  // [i] traversal unit i's leaf, [units] INT's next triangle
  TimedCache lcache, icache;
  MemoryRead rs1;
  LatencyPipe<RayToken> intPipe;
  Fifo intList, intLarb;
  int intShaderNumLeft;  // the shadow-hit FIFO, never written by primary rays
  LatencyPipe<RayToken> listPipe;
  Fifo listLast;
  LatencyPipe<RayToken> listHitPipe;
  Fifo listHitFifo;
  Register toSs;
  MemoryRead rs2;
  RotatingArbiter<RayToken> shaderArb;
  LatencyPipe<RayToken> shaderPipe;
  Fifo shaderData, pixelBuffer;
  int64_t leafReads[2] = {-2, -2};  // the list unit's last two leaf_max reads (list_unit.sv)
  int leafMaxPointer = 0;           // rrp: which unit's leaf_max write waits on a conflict
};

}  // namespace raypipe_timed
}  // namespace rtu
