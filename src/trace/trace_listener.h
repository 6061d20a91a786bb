#pragma once
// A consumer of a trace's records besides its file (src/trace/cycle_trace.h): the timeline
// (src/trace/timeline_writer.h) and the dry run that measures a trace before it is written
// (src/run/trace_plan.h). A listener sees every signal the modules declare, whatever the file's
// scope filter and cycle window, and the changes of each cycle once it is final, in time order.
// A listener with a window of its own (a windowed timeline) hears, before the window, only the
// signals it needs there, then the values the others hold, and nothing once it is satisfied: so
// it costs about its window, as the file's window does.

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

  // The first cycle whose every change the listener needs; before it the trace tells it only the
  // changes of the signals needsBefore() names, then, once, the values the others hold (held()),
  // before any change of that cycle.
  virtual uint64_t listensFrom() const { return 0; }
  // Called after declared(): whether the changes of this signal before listensFrom() matter.
  virtual bool needsBefore(const std::string& /*scope*/, const TraceVariable& /*variable*/) const {
    return true;
  }
  // The values of the signals needsBefore() left out, as of `cycle` (listensFrom() - 1): each one
  // recorded before listensFrom(), with its latest value.
  virtual void held(uint64_t /*cycle*/, const std::vector<TraceChange>& /*values*/) {}
  // True when no change of `cycle` or later matters to the listener any more (its window, and
  // what started in it, has ended).
  virtual bool satisfiedBefore(uint64_t /*cycle*/) const { return false; }
};

}  // namespace rtu
