#pragma once
// The file side of a trace (src/trace/cycle_trace.h): declarations nested by scope, then value
// changes in time order. One writer per format; the format follows the path's extension.

#include <cstdint>
#include <memory>
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
  // The values at the first time: every variable once, between these two calls.
  virtual void beginInitial(uint64_t timePs) = 0;
  virtual void endInitial() = 0;
  virtual void time(uint64_t timePs) = 0;
  virtual void value(size_t index, bool known, uint64_t value) = 0;
  // Throws std::runtime_error naming the file when it could not be written.
  virtual void close() = 0;
  // The bytes written so far by a counting writer (openVcdCounter); 0 for a file.
  virtual uint64_t bytes() const { return 0; }
};

class CountingStream;

// FST (compressed, with enum tables for named values) for a path ending in ".fst", else VCD.
// Throws std::runtime_error when the file cannot be created.
std::unique_ptr<TraceWriter> openTraceWriter(const std::string& path);
std::unique_ptr<TraceWriter> openVcdWriter(const std::string& path);
std::unique_ptr<TraceWriter> openFstWriter(const std::string& path);
// Writes the VCD into `counter` (which must outlive it), which only counts its bytes.
std::unique_ptr<TraceWriter> openVcdCounter(CountingStream& counter);

// `value`'s low `width` bits, most significant first.
std::string bitString(uint64_t value, int width);

}  // namespace rtu
