#pragma once
// A value-change-dump (VCD) recorder in clock cycles, for GTKWave. Modules record a value with the
// cycle it takes effect, which may lie ahead of simulated time: a core that runs ahead through
// cycles nothing else can observe still records each state in its own cycle. Only a cycle window
// and the module scopes asked for are kept, so traces of long runs stay small.

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace rtu {

struct TraceOptions {
  std::string path;
  uint64_t fromCycle = 0;
  uint64_t toCycle = std::numeric_limits<uint64_t>::max();  // exclusive
  std::vector<std::string> scopes;                          // scope prefixes; empty keeps all
  uint64_t periodPs = 10000;                                // VCD time of one cycle
};

class CycleTrace {
 public:
  static constexpr int kNoSignal = -1;

  explicit CycleTrace(TraceOptions options);

  // A signal of `width` bits (1 to 64) in the dot-separated module path `scope`; kNoSignal when
  // the scope filter leaves it out.
  int declare(const std::string& scope, const std::string& name, int width);
  // The value `signal` holds from `cycle` on. Within one cycle the last record wins.
  void record(int signal, uint64_t cycle, uint64_t value);

  // Writes the VCD file; throws std::runtime_error when it cannot be written.
  void write() const;

 private:
  struct Signal {
    std::string scope, name, code;
    int width;
    bool hasInitial = false;
    uint64_t initialCycle = 0, initialValue = 0;
  };
  struct Change {
    uint64_t cycle;
    int signal;
    uint64_t value;
  };
  bool scopeKept(const std::string& scope) const;

  TraceOptions options_;
  std::vector<Signal> signals_;
  std::vector<Change> changes_;
};

}  // namespace rtu
