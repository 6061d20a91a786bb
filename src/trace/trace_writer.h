#pragma once
// The file side of a trace (src/trace/cycle_trace.h): declarations nested by scope, then value
// changes in time order. One writer per format; the format follows the path's extension.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rtu {

struct TraceVariable {
  std::string name;
  int width;
  std::vector<std::string> valueNames;  // names of the values 0, 1, ...; empty for numbers
};

class TraceWriter {
 public:
  virtual ~TraceWriter() = default;
  virtual void enterScope(const std::string& name) = 0;
  virtual void leaveScope() = 0;
  // `index` is the variable's number in value(): 0, 1, ... in any order.
  virtual void variable(size_t index, const TraceVariable& variable) = 0;
  virtual void endDeclarations() = 0;
  // The values at the first time: every variable once, between these two calls. Times are in
  // the writer's unit (TraceTimeUnit).
  virtual void beginInitial(uint64_t time) = 0;
  virtual void endInitial() = 0;
  virtual void time(uint64_t time) = 0;
  virtual void value(size_t index, bool known, uint64_t value) = 0;
  // Throws std::runtime_error naming the file when it could not be written.
  virtual void close() = 0;
  // The bytes written so far by a counting writer (openVcdCounter); 0 for a file.
  virtual uint64_t bytes() const { return 0; }
};

class CountingStream;

// A trace's time unit: 10^exponent seconds (VCD and FST timescales are powers of ten: a 1, 10 or
// 100 times a second's power of a thousand).
struct TraceTimeUnit {
  int exponent = -12;  // 1 ps
  // The unit of `ps` picoseconds when it is a power of ten, else none.
  static std::optional<TraceTimeUnit> ofPicoseconds(uint64_t ps);
  uint64_t picoseconds() const;      // for exponents from -12 up
  std::string vcdTimescale() const;  // "1ps", "10ns", "100us", ...
  // GTKWave keeps a trace's times in the timescale's power of a thousand (1 ns for 10 ns), so a
  // save file's times are the trace's times this many times (1, 10 or 100).
  uint64_t viewerFactor() const;
};

// FST (compressed, with enum tables for named values) for a path ending in ".fst", else VCD.
// Throws std::runtime_error when the file cannot be created.
std::unique_ptr<TraceWriter> openTraceWriter(const std::string& path, TraceTimeUnit unit);
std::unique_ptr<TraceWriter> openVcdWriter(const std::string& path, TraceTimeUnit unit);
std::unique_ptr<TraceWriter> openFstWriter(const std::string& path, TraceTimeUnit unit);
// Writes the VCD into `counter` (which must outlive it), which only counts its bytes.
std::unique_ptr<TraceWriter> openVcdCounter(CountingStream& counter, TraceTimeUnit unit);

// `value`'s low `width` bits, most significant first.
std::string bitString(uint64_t value, int width);

}  // namespace rtu
