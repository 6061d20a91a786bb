#pragma once
// The timed ray pipe's cycle trace (issue 29 §2; docs/raypipe.md, "Traces"): what each unit did in
// each cycle and how full each FIFO was, through the trace recorder (trace/cycle_trace.h) for
// GTKWave. Scopes, in the pipe's order (RaypipeUnit):
//   raypipe.<unit>.valid, .stall  an item was offered to the unit in the cycle, and it was not
//                                 taken (valid & ~stall: the unit took it, the RTL's transfer)
//   raypipe.<unit>.ray            the ray id of the item it took last (the PRG: .pixel, the
//                                 pixel's place in its issue order, as no ray id is given yet)
//   raypipe.fifos.<fifo>.count    the entries at the cycle's start (the RTL's usedw: a write or a
//                                 read in cycle t counts from t + 1)
//   raypipe.fifos.<fifo>.ray      the ray id at its head (prg: .pixel; shader_ray_ids: the next
//                                 free id), from the same cycle
// The model calls it only for what happens (a unit's transfer or stall, a FIFO's write or read),
// so an idle stretch costs nothing here either; every record is for the current cycle or the
// next, except the stall cycles the PRG's group adds up at its next call (timed_front.cpp), which
// lie after its last call: flushes stop there (safeCycle).

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "raypipe/raypipe_config.h"
#include "raypipe/raypipe_run.h"
#include "trace/cycle_trace.h"

namespace rtu {
namespace raypipe_timed {

// The bits that hold the values 0 .. count - 1 (at least one).
int traceWidth(uint64_t count);

// A FIFO's two signals (TimedQueue calls changed() on every write and read once traced).
class FifoTrace {
 public:
  FifoTrace(CycleTrace& trace, const std::string& fifo, int depth, int idWidth, bool pixels);
  bool pixels() const { return pixels_; }
  // After a write or read in `cycle`: `count` entries, `head` at the head when count > 0.
  void changed(int64_t cycle, int count, uint64_t head);

 private:
  CycleTrace& trace_;
  int count_, head_;
  bool pixels_;
};

class PipeTrace {
 public:
  PipeTrace(CycleTrace& trace, const RaypipeConfig& config, size_t rays);
  // `unit` took the item of ray id (PRG: pixel) `id` in `cycle`.
  void took(RaypipeUnit unit, int64_t cycle, uint64_t id);
  // An item was offered to `unit` and stalled in every cycle of [from, to).
  void stalled(RaypipeUnit unit, int64_t from, int64_t to);
  FifoTrace& fifo(const std::string& name, int depth, bool pixels = false);
  // Writes the cycles before `cycle` (no record for them can come any more).
  void flush(int64_t cycle) { trace_.flush(static_cast<uint64_t>(cycle)); }
  // The rest, and the save file with its marker at `marker` (the first pixel's exit).
  void finish(int64_t marker) { trace_.finish(static_cast<uint64_t>(marker)); }

 private:
  struct UnitSignals {
    int valid, stall, id;
  };
  CycleTrace& trace_;
  int idWidth_, pixelWidth_;
  std::vector<UnitSignals> units_;
  std::deque<FifoTrace> fifos_;  // fifo() hands out references: no reallocation
};

}  // namespace raypipe_timed
}  // namespace rtu
