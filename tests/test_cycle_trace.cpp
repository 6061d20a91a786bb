// The streaming trace recorder (src/trace/cycle_trace.h) on its own: records arrive ahead of the
// flushed cycle and out of time order, and the file holds them in time order, each cycle's last
// record winning, exactly as if the whole trace had been held until the end; a record for a cycle
// already written is refused.

#include <unistd.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "trace/cycle_trace.h"
#include "trace/gtkw_save_file.h"
#include "trace/instance_names.h"
#include "trace/trace_writer.h"

namespace rtu {
namespace {

namespace fs = std::filesystem;

std::string tracePath(const std::string& name) {
  return (fs::temp_directory_path() / ("rtusim_trace_" + std::to_string(getpid()) + "_" + name))
      .string();
}

std::string contents(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A finished trace's text; the trace and its save file removed.
std::string takenTrace(const std::string& path) {
  const std::string text = contents(path);
  fs::remove(path);
  fs::remove(saveFilePath(path));
  return text;
}

// Two signals, the same records, written through `flushes` (cycles flushed in between).
std::string recorded(const std::string& name, bool flushInBetween) {
  TraceOptions options;
  options.path = tracePath(name);
  options.periodPs = 10;
  options.time = TraceTime::Picoseconds;
  CycleTrace trace(options);
  const int state = trace.declare("top.core_0", "state", 3);
  const int valid = trace.declare("top.in", "valid", 1);
  trace.record(state, 0, 0);
  trace.record(valid, 0, 0);
  trace.record(state, 5, 2);  // a core running ahead
  trace.record(state, 3, 1);
  trace.record(valid, 2, 1);
  if (flushInBetween) {
    trace.flush(3);  // cycles 0..2 final
    CHECK(trace.pendingRecords() == 2);
  }
  trace.record(valid, 3, 0);
  trace.record(state, 6, 4);
  trace.record(state, 6, 5);  // the last record of a cycle wins
  trace.record(valid, 4, 0);  // no change: not written
  if (flushInBetween) trace.flush(5);
  trace.record(state, 5, 3);  // replaces the early record of cycle 5
  trace.finish(0);
  const std::string text = contents(options.path);
  fs::remove(options.path);
  return text;
}

TEST_CASE("Trace streaming writes cycles in time order as they become final", "[trace]") {
  const std::string streamed = recorded("streamed.vcd", true);
  CHECK(streamed == recorded("whole.vcd", false));
  const std::string changes = streamed.substr(streamed.find("$dumpvars"));
  CHECK(changes ==
        "$dumpvars\nb000 !\n0\"\n$end\n#20\n1\"\n#30\nb001 !\n0\"\n#50\nb011 !\n#60\nb101 !\n");
}

// Random records arriving ahead and out of order, flushed as they become final: records that span
// few cycles against their number are sorted by counting, others by a merge sort; both give the
// trace of the same records held to the end.
std::string randomRecords(const std::string& name, uint64_t flushCycles, bool flushInBetween) {
  TraceOptions options;
  options.path = tracePath(name);
  options.periodPs = 1;
  options.flushCycles = flushCycles;
  CycleTrace trace(options);
  const std::vector<int> signals{trace.declare("top.a", "x", 8), trace.declare("top.b", "y", 8),
                                 trace.declare("top.c", "z", 1)};
  uint64_t state = 12345, final = 0;
  const auto next = [&state](uint64_t range) {
    state = state * 6364136223846793005u + 1442695040888963407u;
    return (state >> 33) % range;
  };
  for (int round = 0; round < 300; ++round) {
    const bool sparse = round % 3 == 0;  // some flushes see records thousands of cycles apart
    for (int i = 0; i < 1 + static_cast<int>(next(6)); ++i) {
      const int signal = signals[next(signals.size())];
      trace.record(signal, final + next(sparse ? 5000 : 8), next(signal == signals[2] ? 2 : 256));
    }
    if (next(2) == 0) {  // the same records whether flushed or not
      final += next(4);
      if (flushInBetween) trace.flush(final);
    }
  }
  trace.finish(0);
  return takenTrace(options.path);
}

TEST_CASE("Trace streaming: records over many cycles or few give the trace held to the end",
          "[trace]") {
  const std::string whole = randomRecords("random_whole.vcd", 4096, false);
  CHECK(randomRecords("random_counted.vcd", 1u << 20, true) == whole);  // counting sort always
  CHECK(randomRecords("random_merged.vcd", 1, true) == whole);  // the merge sort on sparse flushes
  CHECK(whole.find("#4") != std::string::npos);
}

TEST_CASE("Trace time units: a period of a power of ten picoseconds is a timescale", "[trace]") {
  const std::vector<std::tuple<uint64_t, int, std::string>> units{
      {1, -12, "1ps"},     {10, -11, "10ps"},     {1000, -9, "1ns"},
      {10000, -8, "10ns"}, {100000, -7, "100ns"}, {1000000, -6, "1us"}};
  for (const auto& [ps, exponent, text] : units) {
    const std::optional<TraceTimeUnit> unit = TraceTimeUnit::ofPicoseconds(ps);
    REQUIRE(unit);
    CHECK(unit->exponent == exponent);
    CHECK(unit->vcdTimescale() == text);
    CHECK(unit->picoseconds() == ps);
    CHECK(unit->viewerFactor() == (text[1] == '0' ? (text[2] == '0' ? 100u : 10u) : 1u));
  }
  for (uint64_t ps : {0, 4000, 6667, 20000}) CHECK_FALSE(TraceTimeUnit::ofPicoseconds(ps));
}

// One signal at 100 MHz (10 ns), changing in cycles 0, 2 and 7.
std::string timedTrace(const std::string& name, TraceTime time, uint64_t periodPs = 10000) {
  TraceOptions options;
  options.path = tracePath(name);
  options.periodPs = periodPs;
  options.time = time;
  CycleTrace trace(options);
  const int level = trace.declare("top", "level", 1);
  trace.record(level, 0, 0);
  trace.record(level, 2, 1);
  trace.record(level, 7, 0);
  trace.finish(2);
  return takenTrace(options.path);
}

TEST_CASE("Trace time: cycle numbers in a timescale of the clock period\\, or picoseconds",
          "[trace]") {
  const std::string cycles = timedTrace("cycles.vcd", TraceTime::Auto);
  CHECK(cycles.find("$timescale 10ns $end") == 0);
  CHECK(cycles.substr(cycles.find("$dumpvars")) == "$dumpvars\n0!\n$end\n#2\n1!\n#7\n0!\n");
  const std::string ps = timedTrace("ps.vcd", TraceTime::Picoseconds);
  CHECK(ps.find("$timescale 1ps $end") == 0);
  CHECK(ps.substr(ps.find("$dumpvars")) == "$dumpvars\n0!\n$end\n#20000\n1!\n#70000\n0!\n");
  // 4 ns is no timescale: auto traces in picoseconds, cycles are refused.
  CHECK(timedTrace("auto4ns.vcd", TraceTime::Auto, 4000).find("$timescale 1ps $end") == 0);
  CHECK_THROWS_WITH(timedTrace("cycles4ns.vcd", TraceTime::Cycles, 4000),
                    Catch::Contains("this clock's is 4000 ps"));
}

TEST_CASE("Trace refuses a record behind the written cycles and a late declaration", "[trace]") {
  TraceOptions options;
  options.path = tracePath("late.vcd");
  CycleTrace trace(options);
  const int state = trace.declare("top", "state", 3);
  trace.record(state, 10, 1);
  trace.flush(8);
  CHECK_NOTHROW(trace.record(state, 8, 2));
  CHECK_THROWS_AS(trace.record(state, 7, 2), std::logic_error);
  CHECK_THROWS_AS(trace.declare("top", "late", 1), std::logic_error);
  trace.finish(0);
  fs::remove(options.path);
}

TEST_CASE("Trace window: records before it set the initial values when it starts", "[trace]") {
  TraceOptions options;
  options.path = tracePath("window.vcd");
  options.fromCycle = 4;
  options.toCycle = 6;
  options.periodPs = 1;
  CycleTrace trace(options);
  const int level = trace.declare("top", "level", 1);
  trace.record(level, 1, 1);
  trace.flush(3);  // the window has not started: nothing written but the declarations
  trace.record(level, 3, 0);
  trace.record(level, 5, 1);
  trace.record(level, 6, 0);  // after the window
  trace.finish(0);
  const std::string text = contents(options.path);
  fs::remove(options.path);
  CHECK(text.substr(text.find("#4")) == "#4\n$dumpvars\n0!\n$end\n#5\n1!\n");
}

// Before the window nothing is queued (so its cycles cost little): each signal keeps its latest
// record, by cycle, the last to arrive within a cycle.
TEST_CASE("Trace window: records before it are held in place, the latest cycle winning",
          "[trace]") {
  TraceOptions options;
  options.path = tracePath("held.vcd");
  options.fromCycle = 10;
  options.periodPs = 1;
  CycleTrace trace(options);
  const int a = trace.declare("top", "a", 1);
  const int b = trace.declare("top", "b", 1);
  const int c = trace.declare("top", "c", 1);
  trace.record(a, 7, 1);
  trace.record(a, 5, 0);  // an earlier cycle arriving later: not the value at the window
  trace.record(b, 8, 0);
  trace.record(b, 8, 1);  // the same cycle: the last record wins
  CHECK(trace.pendingRecords() == 0);
  trace.record(c, 10, 1);  // in the window: queued
  CHECK(trace.pendingRecords() == 1);
  trace.finish(0);
  const std::string text = contents(options.path);
  fs::remove(options.path);
  fs::remove(saveFilePath(options.path));
  CHECK(text.substr(text.find("#10")) == "#10\n$dumpvars\n1!\n1\"\n1#\n$end\n");
}

// What a listener is told.
struct Heard : TraceListener {
  std::vector<std::string> scopes;
  std::vector<std::tuple<uint64_t, size_t, uint64_t>> changes;
  bool finishedCalled = false;
  void declared(size_t signal, const std::string& scope, const TraceVariable&) override {
    CHECK(signal == scopes.size());
    scopes.push_back(scope);
  }
  void changed(uint64_t cycle, const std::vector<TraceChange>& values) override {
    for (const TraceChange& change : values)
      changes.emplace_back(cycle, change.signal, change.value);
  }
  void finished() override { finishedCalled = true; }
};

TEST_CASE("Trace listeners hear every signal and cycle, whatever the file keeps", "[trace]") {
  TraceOptions options;
  options.path = tracePath("listened.vcd");
  options.scopes = {"top.in"};
  options.fromCycle = 4;
  Heard heard;
  CycleTrace trace(options, {&heard});
  const int state = trace.declare("top.core_0", "state", 3);  // outside the file's scope
  const int valid = trace.declare("top.in", "valid", 1);
  REQUIRE(state != CycleTrace::kNoSignal);
  trace.record(state, 0, 0);
  trace.record(valid, 0, 0);
  trace.record(state, 5, 2);  // ahead, out of order
  trace.record(state, 1, 1);
  trace.flush(3);
  trace.record(state, 3, 1);  // no change: not heard
  trace.record(valid, 3, 1);
  trace.record(state, 5, 3);  // the last record of the cycle wins
  trace.finish(0);
  fs::remove(options.path);
  fs::remove(saveFilePath(options.path));
  CHECK(heard.scopes == std::vector<std::string>{"top.core_0", "top.in"});
  const std::vector<std::tuple<uint64_t, size_t, uint64_t>> expected{
      {0, 0, 0}, {0, 1, 0}, {1, 0, 1}, {3, 1, 1}, {5, 0, 3}};
  CHECK(heard.changes == expected);
  CHECK(heard.finishedCalled);
}

// A listener with a window of its own (a windowed timeline): before it only the changes it
// needs there, then the values of the others held in place, and nothing once it is satisfied.
struct WindowedHeard : Heard {
  uint64_t from = 10, satisfiedFrom = 20;
  std::vector<std::tuple<uint64_t, size_t, uint64_t>> heldValues;
  uint64_t listensFrom() const override { return from; }
  bool needsBefore(const std::string&, const TraceVariable& variable) const override {
    return variable.name == "valid";
  }
  void held(uint64_t cycle, const std::vector<TraceChange>& values) override {
    for (const TraceChange& value : values)
      heldValues.emplace_back(cycle, value.signal, value.value);
  }
  bool satisfiedBefore(uint64_t cycle) const override { return cycle >= satisfiedFrom; }
};

TEST_CASE("A listener with a window hears its early signals\\, the held values\\, then all",
          "[trace]") {
  WindowedHeard heard;
  CycleTrace trace(TraceOptions{}, {&heard});
  const int state = trace.declare("top.core_0", "state", 3);
  const int valid = trace.declare("top.in", "valid", 1);
  trace.record(state, 2, 1);
  trace.record(state, 7, 2);
  trace.record(state, 5, 3);  // an earlier cycle arriving later: not the value held
  trace.record(valid, 3, 1);
  CHECK(trace.pendingRecords() == 1);  // the state is held in place
  trace.flush(8);
  CHECK(heard.heldValues.empty());  // cycles 8 and 9 are not final yet
  trace.record(state, 12, 4);
  trace.record(valid, 12, 0);
  trace.flush(16);
  CHECK_FALSE(trace.listenersSatisfied());
  trace.flush(24);
  CHECK(trace.listenersSatisfied());
  trace.record(state, 30, 5);  // after the listener is satisfied: not queued
  CHECK(trace.pendingRecords() == 0);
  trace.finish(0);
  const std::vector<std::tuple<uint64_t, size_t, uint64_t>> changes{
      {3, 1, 1}, {12, 0, 4}, {12, 1, 0}};
  CHECK(heard.changes == changes);
  const std::vector<std::tuple<uint64_t, size_t, uint64_t>> held{{9, 0, 2}};
  CHECK(heard.heldValues == held);
}

TEST_CASE("A counting trace counts the bytes of the VCD it would write", "[trace]") {
  const auto run = [](TraceOptions options) {
    CycleTrace trace(options);
    const int state = trace.declare("top.core_0", "state", 3, {"A", "B", "C"});
    const int valid = trace.declare("top.in", "valid", 1);
    for (uint64_t cycle = 0; cycle < 300; ++cycle) {
      trace.record(state, cycle, cycle / 7 % 3);
      trace.record(valid, cycle, cycle / 3 % 2);
    }
    trace.finish(0);
    return trace.countedBytes();
  };
  TraceOptions written;
  written.path = tracePath("counted.vcd");
  run(written);
  TraceOptions counted = written;
  counted.countOnly = true;
  CHECK(run(counted) == fs::file_size(written.path));
  fs::remove(written.path);
  fs::remove(saveFilePath(written.path));
}

TEST_CASE("Instance numbers are padded to the widest of their kind", "[trace]") {
  CHECK(unpaddedScope("rtu.core_03.in") == "rtu.core_3.in");
  CHECK(unpaddedScope("rtu.core_00") == "rtu.core_0");
  InstanceWidths four, twelve;
  for (int i = 0; i < 4; ++i) four.add("rtu.core_" + std::to_string(i));
  for (int i = 0; i < 12; ++i) {
    twelve.add("rtu.core_" + std::to_string(i) + ".in");
    twelve.add("rtu.memory.l1_" + std::to_string(i));
  }
  CHECK(four.padded("rtu.core_3.in") == "rtu.core_3.in");
  CHECK(twelve.padded("rtu.core_3.in") == "rtu.core_03.in");
  CHECK(twelve.padded("rtu.core_11") == "rtu.core_11");
  CHECK(twelve.padded("rtu.memory.l1_0") == "rtu.memory.l1_00");
  CHECK(twelve.padded("rtu.memory.l2") == "rtu.memory.l2");
  CHECK(twelve.padded("rtu.job_manager.in") == "rtu.job_manager.in");
}

}  // namespace
}  // namespace rtu
