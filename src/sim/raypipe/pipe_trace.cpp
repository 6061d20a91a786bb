// The timed ray pipe's cycle trace (pipe_trace.h).
#include "sim/raypipe/pipe_trace.h"

#include <algorithm>

namespace rtu {
namespace raypipe_timed {
namespace {

const std::string kTop = "raypipe";

// A record for a cycle before the run's first (the shader's ray ids, written at reset) is the
// value the trace starts from.
uint64_t traceCycle(int64_t cycle) { return static_cast<uint64_t>(std::max<int64_t>(cycle, 0)); }

}  // namespace

int traceWidth(uint64_t count) {
  int width = 1;
  while (width < 64 && (uint64_t{1} << width) < count) ++width;
  return width;
}

FifoTrace::FifoTrace(CycleTrace& trace, const std::string& fifo, int depth, int idWidth,
                     bool pixels)
    : trace_(trace),
      count_(trace.declare(kTop + ".fifos." + fifo, "count",
                           traceWidth(static_cast<uint64_t>(depth) + 1))),
      head_(trace.declare(kTop + ".fifos." + fifo, pixels ? "pixel" : "ray", idWidth)),
      pixels_(pixels) {
  trace_.record(count_, 0, 0);
  trace_.record(head_, 0, 0);
}

void FifoTrace::changed(int64_t cycle, int count, uint64_t head) {
  trace_.record(count_, traceCycle(cycle), static_cast<uint64_t>(count));
  if (count > 0) trace_.record(head_, traceCycle(cycle), head);
}

PipeTrace::PipeTrace(CycleTrace& trace, const RaypipeConfig& config, size_t rays)
    : trace_(trace),
      idWidth_(traceWidth(static_cast<uint64_t>(config.raysInFlight))),
      pixelWidth_(traceWidth(rays)) {
  for (size_t u = 0; u < static_cast<size_t>(RaypipeUnit::kCount); ++u) {
    const RaypipeUnit unit = static_cast<RaypipeUnit>(u);
    const std::string scope = kTop + "." + raypipeUnitName(unit);
    const bool prg = unit == RaypipeUnit::Prg;
    const UnitSignals s{trace.declare(scope, "valid", 1), trace.declare(scope, "stall", 1),
                        trace.declare(scope, prg ? "pixel" : "ray", prg ? pixelWidth_ : idWidth_)};
    for (int signal : {s.valid, s.stall, s.id}) trace.record(signal, 0, 0);
    units_.push_back(s);
  }
}

void PipeTrace::took(RaypipeUnit unit, int64_t cycle, uint64_t id) {
  const UnitSignals& s = units_[static_cast<size_t>(unit)];
  const uint64_t c = traceCycle(cycle);
  trace_.record(s.valid, c, 1);
  trace_.record(s.stall, c, 0);
  trace_.record(s.id, c, id);
  trace_.record(s.valid, c + 1, 0);
}

void PipeTrace::stalled(RaypipeUnit unit, int64_t from, int64_t to) {
  if (to <= from) return;
  const UnitSignals& s = units_[static_cast<size_t>(unit)];
  trace_.record(s.valid, traceCycle(from), 1);
  trace_.record(s.stall, traceCycle(from), 1);
  trace_.record(s.valid, traceCycle(to), 0);
  trace_.record(s.stall, traceCycle(to), 0);
}

FifoTrace& PipeTrace::fifo(const std::string& name, int depth, bool pixels) {
  fifos_.emplace_back(trace_, name, depth, pixels ? pixelWidth_ : idWidth_, pixels);
  return fifos_.back();
}

}  // namespace raypipe_timed
}  // namespace rtu
