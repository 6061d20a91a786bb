#pragma once
// A per-core timeline of a run in the Chrome trace-event JSON that Perfetto (ui.perfetto.dev) and
// chrome://tracing open: the picture for runs too long for a waveform. Built from the trace's
// records (a TraceListener of src/trace/cycle_trace.h), so it needs no hook in the modules:
// - each core a track; each ray a slice from the cycle its core leaves IDLE (SVO: its INIT) to
//   the cycle its result is handed over,
//   named after its job sequence number, with nested BLOCKED slices (waiting for memory) and an
//   OUT slice (the result waiting for the result manager);
// - counters: jobs inside the job manager, a pending job the scheduler cannot place, results
//   held by the result manager and by the reorder buffer.
// Ray numbers: the id a core's input channel carries (class "ids", the host record's index) when
// the core leaves IDLE, one cycle after its handshake.
// A window (--trace-from/--trace-to, --trace-ray) keeps the rays that start in it and the
// counters in it, and costs about its own cycles (TraceListener's window): before it the
// timeline hears only the handshakes its counters count, then the values the rest holds, and
// nothing once the window and the rays that started in it have ended.
// Time stamps are simulated time in microseconds (at 100 MHz a cycle is 0.01 us), exact to the
// picosecond. Events carry nothing else, to keep the file small (docs/waveforms.md).

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "base/output_file.h"
#include "rtu/core_kind.h"
#include "trace/trace_listener.h"

namespace rtu {

struct TimelineOptions {
  std::string path;        // empty: none
  uint64_t fromCycle = 0;  // rays that start in the window, counters sampled in it
  uint64_t toCycle = std::numeric_limits<uint64_t>::max();  // exclusive
  bool countOnly = false;  // write nothing, only count the bytes (bytes())

  bool wanted() const { return !path.empty(); }
};

class TimelineWriter : public TraceListener {
 public:
  // Throws std::runtime_error when the file cannot be created.
  // `states` names the cores' trace codes (their kind's vocabulary).
  TimelineWriter(TimelineOptions options, uint64_t periodPs, StateVocabulary states);

  void declared(size_t signal, const std::string& scope, const TraceVariable& variable) override;
  void changed(uint64_t cycle, const std::vector<TraceChange>& changes) override;
  // Closes the JSON; throws std::runtime_error when the file could not be written.
  void finished() override;
  uint64_t listensFrom() const override { return options_.fromCycle; }
  bool needsBefore(const std::string& scope, const TraceVariable& variable) const override;
  void held(uint64_t cycle, const std::vector<TraceChange>& values) override;
  bool satisfiedBefore(uint64_t cycle) const override;

  // Bytes of the JSON so far, written or counted.
  uint64_t bytes() const { return bytes_; }

 private:
  enum class Role { None, CoreState, Valid, Ready, CoreRay };
  struct SignalRole {
    Role role = Role::None;
    size_t index = 0;  // core or channel
  };
  static constexpr size_t kNone = static_cast<size_t>(-1);
  enum : size_t { kJobCounter, kWaitCounter, kResultCounter, kReorderCounter };
  struct Channel {
    std::string key;  // the scope below the top, e.g. scheduler.in
    bool valid = false, ready = false;
    size_t into = kNone, outOf = kNone;  // the counters a transfer adds to, takes from
  };
  struct Core {
    uint64_t state = 0;
    uint64_t ray = 0, start = 0, blockedStart = 0, outStart = 0;
    uint64_t offered = 0;  // the ray its input channel carries
  };
  struct Counter {
    std::string name, unit;
    int64_t held = 0;      // jobs or results held, as of the timeline's cursor
    int64_t written = -1;  // last written; -1: none yet
  };

  size_t channel(const std::string& key);
  void apply(uint64_t cycle, const std::vector<TraceChange>& changes);
  void level(const SignalRole& role, uint64_t value);
  void findStreaming();
  void advanceTo(uint64_t cycle);
  void coreState(size_t core, uint64_t cycle, uint64_t state);
  void slice(size_t core, const std::string& name, uint64_t from, uint64_t to);
  void sampleCounters(uint64_t cycle);
  void transfer(const Channel& channel);
  void assignCounters();
  void writeHeader();
  void event(const std::string& json);
  bool inWindow(uint64_t cycle) const;
  std::string time(uint64_t cycle) const;

  TimelineOptions options_;
  uint64_t periodPs_;
  StateVocabulary states_;
  std::optional<OutputFile> file_;  // none when only counting
  uint64_t bytes_ = 0;
  std::vector<SignalRole> roles_;
  std::vector<Channel> channels_;
  std::vector<size_t> streaming_;  // channels with valid and ready high: a transfer every cycle
  std::vector<Core> cores_;
  std::vector<Counter> counters_;
  size_t waitChannel_ = kNone;  // scheduler.in
  uint64_t cursor_ = 0;         // channel transfers are counted up to this cycle
  bool started_ = false, firstEvent_ = true;
};

}  // namespace rtu
