#pragma once
// The timed model of seed 001's ray pipe: a block-RAM read and the FIFOs' show delays.

#include <cstdint>
#include <string>

#include "sim/raypipe/latency_pipe.h"
#include "sim/raypipe/ray_token.h"
#include "sim/raypipe/timed_queue.h"

namespace rtu {
namespace raypipe_timed {

constexpr int kRegister = 1;   // a register FIFO shows a write the next cycle
constexpr int kShowAhead = 2;  // a BRAM scfifo two cycles on

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

}  // namespace raypipe_timed
}  // namespace rtu
