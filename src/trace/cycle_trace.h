#pragma once
// A trace recorder in clock cycles, for GTKWave: FST or VCD (src/trace/trace_writer.h). Modules
// record a value with the cycle it takes effect, which may lie ahead of simulated time (a core
// that runs ahead through cycles nothing else can observe still records each state in its own
// cycle) but never behind it.
// So every cycle before the current simulated one is final: the simulation calls flush() with
// that cycle now and then, which writes those cycles in time order and frees them; only the
// records ahead of simulated time stay in memory, whatever the length of the run. Only a cycle
// window and the module scopes asked for go to the file (instances numbered core_03 when there
// are ten or more: src/trace/instance_names.h); listeners (src/trace/trace_listener.h) see
// every signal and every cycle.

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "base/counting_stream.h"
#include "trace/trace_listener.h"
#include "trace/trace_writer.h"

namespace rtu {

// The trace's time axis: cycles (a unit a clock period, so GTKWave shows cycle numbers) or
// picoseconds. Auto: cycles when the period is a power of ten of picoseconds (100 MHz: 10 ns) and
// no clock is traced (its falling edges are in mid-cycle), else picoseconds.
enum class TraceTime { Auto, Cycles, Picoseconds };

struct TraceOptions {
  std::string path;  // empty: no file, only the listeners
  uint64_t fromCycle = 0;
  uint64_t toCycle = std::numeric_limits<uint64_t>::max();  // exclusive
  std::vector<std::string> scopes;                          // scope prefixes; empty keeps all
  std::vector<std::string> signalClasses;  // src/trace/trace_signal_classes.h; empty keeps all
  uint64_t periodPs = 10000;               // trace time of one cycle
  uint64_t flushCycles = 4096;  // how often the simulation writes the final cycles (memory bound)
  bool countOnly = false;       // write nothing: count the bytes of the VCD the file would be
  // A clock `clk` in the top scope, high in the first half of every cycle from the window's first
  // cycle to its last change (two changes per cycle: a trace of every cycle).
  bool clock = false;
  // The module whose group the save file shows first ("core_3": the core of --trace-ray's ray);
  // empty: pipeline order only.
  std::string firstModule = {};
  TraceTime time = TraceTime::Auto;
  // The save file's marker (--trace-ray: the ray's result at the host); none: the first result.
  // A marker outside the window moves to its first cycle.
  std::optional<uint64_t> markerCycle = {};
};

class CycleTrace {
 public:
  static constexpr int kNoSignal = -1;

  // Opens the file; throws std::runtime_error when it cannot be written. The listeners must
  // outlive the trace.
  explicit CycleTrace(TraceOptions options, std::vector<TraceListener*> listeners = {});

  // A signal of `width` bits (1 to 64) in the dot-separated module path `scope`; kNoSignal when
  // the scope filter leaves it out. `valueNames` name the values 0, 1, ... (FST shows them). All
  // signals are declared before the first flush.
  int declare(const std::string& scope, const std::string& name, int width,
              std::vector<std::string> valueNames = {});
  // The value `signal` holds from `cycle` on. Within one cycle the last record wins. Throws
  // std::logic_error for a cycle already written.
  void record(int signal, uint64_t cycle, uint64_t value);

  // Throws std::invalid_argument, listing the scopes declared, when a scope of the filter matched
  // none of them (a typo, or core_7 of 4 cores), or when the scopes and signal classes together
  // keep no signal for the file. Called once every signal is declared.
  void checkScopesMatched() const;

  // Writes every cycle before `cycle`: no record for them can arrive any more.
  void flush(uint64_t cycle);
  // Writes the rest, and a GTKWave save file next to the trace (src/trace/gtkw_save_file.h) shown
  // from the window's first cycle to its last, with a marker at TraceOptions::markerCycle or else
  // `firstResult`; throws std::runtime_error when a file could not be written.
  void finish(uint64_t firstResult);
  // The file's time of a cycle, in its unit (TraceTime).
  uint64_t timeOf(uint64_t cycle) const { return cycle * ticksPerCycle_; }

  // Records held in memory, waiting for their cycle to become final.
  size_t pendingRecords() const { return changes_.size(); }
  // True once every listener is satisfied (TraceListener::satisfiedBefore): it hears no more.
  bool listenersSatisfied() const { return !listening_; }
  // With TraceOptions::countOnly: the bytes the VCD file would have, so far.
  uint64_t countedBytes() const { return writer_ ? writer_->bytes() : 0; }

 private:
  // A signal's latest record before a window, kept in place instead of queued.
  struct Held {
    bool known = false;
    uint64_t cycle = 0, value = 0;
  };
  struct Signal {
    std::string scope;
    TraceVariable variable;
    Held initial = {};
  };
  struct Change {
    uint64_t cycle;
    int signal;
    uint64_t value;
  };
  using Settled = std::vector<TraceChange>;  // a cycle's last record of each signal
  bool scopeKept(const std::string& scope);
  bool classKept(const std::string& name) const;
  void writeDeclarations();
  void chooseTimeUnit();
  // The records in arrival order, ordered by cycle (stably) up to the end.
  void sortPending();
  bool countingSort(std::vector<Change>::iterator begin, std::vector<Change>::iterator end);
  // settled_: the last record of each signal among [begin, end) (one cycle's), by signal.
  void settle(std::vector<Change>::const_iterator begin, std::vector<Change>::const_iterator end);
  void notifyListeners(uint64_t cycle, const Settled& settled);
  static void hold(Held& held, uint64_t cycle, uint64_t value);
  // The listeners' held values, once every cycle before their window is final.
  void tellHeld();
  void checkListenersSatisfied();
  void fileCycle(uint64_t cycle, const Settled& settled);
  void initialValues();
  void writeInitialValues();
  void writeCycle(uint64_t cycle, const Settled& settled);
  void declareClock();
  // The clock's edges of the cycles from clockNext_ up to `end`.
  void clockUpTo(uint64_t end);
  void fallingEdge(uint64_t cycle);

  TraceOptions options_;
  TraceTimeUnit unit_;          // the file's
  uint64_t ticksPerCycle_ = 1;  // the file's time units a cycle
  uint64_t lastFiled_ = 0;      // the last cycle written to the file
  std::vector<TraceListener*> listeners_;
  CountingStream counter_;
  std::unique_ptr<TraceWriter> writer_;
  std::vector<int> fileIndex_;            // per signal id: its index in signals_, or kNoSignal
  std::vector<Signal> signals_;           // the signals the file keeps
  std::set<std::string> declaredScopes_;  // kept or not
  std::vector<bool> scopeMatched_;        // per scope of the filter
  // Records of cycles not yet written: [0, sorted_) ordered by cycle (stably), the rest as they
  // arrived since the last flush.
  std::vector<Change> changes_;
  size_t sorted_ = 0;
  std::vector<size_t> cycleStarts_;  // countingSort's
  std::vector<Change> scratch_;
  Settled settled_, changed_;              // one cycle's, reused from cycle to cycle
  std::vector<size_t> lastRecord_;         // per signal id: settle()'s last record of it
  std::vector<uint64_t> lastRecordRound_;  // per signal id: the settle() that set lastRecord_
  uint64_t settleRound_ = 0;
  uint64_t written_ = 0;  // every cycle before it is written
  bool declared_ = false, dumped_ = false;
  std::vector<bool> known_;  // per signal of the file
  std::vector<uint64_t> current_;
  size_t clockIndex_ = 0;    // the clock's index among the file's signals, with options_.clock
  uint64_t clockNext_ = 0;   // the first cycle whose clock edges are not written
  std::vector<bool> heard_;  // per signal id: the listeners' last values
  std::vector<uint64_t> heardValue_;
  // The listeners' window (TraceListener::listensFrom, the earliest of theirs): before it only
  // the signals marked early are queued for them, the others held.
  uint64_t listenFrom_ = 0;
  bool heldTold_ = true;
  bool listening_ = true;      // false once every listener is satisfied
  std::vector<bool> early_;    // per signal id
  std::vector<Held> heldFor_;  // per signal id: the listeners' values before their window
};

}  // namespace rtu
