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
#include "sim/raypipe/latency_pipe.h"
#include "sim/raypipe/ray_token.h"
#include "sim/raypipe/rotating_arbiter.h"
#include "sim/raypipe/staged_register.h"
#include "sim/raypipe/timed_queue.h"

namespace rtu {
namespace raypipe_timed {

constexpr int kRegister = 1;   // a register FIFO shows a write the next cycle
constexpr int kShowAhead = 2;  // a BRAM scfifo two cycles on

using Unit = RaypipeUnit;
inline const char* unitName(Unit u) { return raypipeUnitName(u); }

// A block-RAM read (simple_cache.sv, raystore_simple.sv): a pipe of the read latency, then a
// 3-entry register FIFO.
struct MemoryRead {
  MemoryRead(const std::string& name, int latency, int depth)
      : pipe(latency), fifo(name, depth, kRegister) {}
  bool usStall(int64_t now, bool dsStall) const {
    return pipe.usStall(now, dsStall, fifo.numLeft(now));
  }
  LatencyPipe<RayToken> pipe;
  TimedQueue<RayToken> fifo;
};

using Fifo = TimedQueue<RayToken>;
using Register = StagedRegister<RayToken>;

// One traversal unit with its tcache and raystore #0 (trav_unit.sv; raypipe_2trav.sv gives each
// of its two units their own): unit 0's FIFOs keep the one-unit build's names, unit i's add _i.
struct TravUnit {
  TravUnit(const RaypipeConfig& c, int i);
  MemoryRead tcache, rs0;
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
  MemoryRead lcache, icache, rs1;
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
