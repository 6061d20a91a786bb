#pragma once
// A consumer of a trace's records besides its file (src/trace/cycle_trace.h): the timeline
// (src/trace/timeline_writer.h) and the dry run that measures a trace before it is written
// (src/run/trace_plan.h). A listener sees every signal the modules declare, whatever the file's
// scope filter and cycle window, and the changes of each cycle once it is final, in time order.

#include <cstdint>
#include <string>
#include <vector>

#include "trace/trace_writer.h"

namespace rtu {

struct TraceChange {
  size_t signal;  // the number declared() gave it
  uint64_t value;
};

class TraceListener {
 public:
  virtual ~TraceListener() = default;
  // Signals are numbered 0, 1, ... in the order they are declared; `scope` is the dot-separated
  // module path, e.g. rtu.core_3.in.
  virtual void declared(size_t signal, const std::string& scope, const TraceVariable& variable) = 0;
  // The signals whose value changed in `cycle` (a signal's first record is a change); called once
  // per cycle with a change, in increasing cycle order.
  virtual void changed(uint64_t cycle, const std::vector<TraceChange>& changes) = 0;
  // The run is over: nothing follows.
  virtual void finished() {}
};

}  // namespace rtu
