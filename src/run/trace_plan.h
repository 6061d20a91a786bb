#pragma once
// Measure first, then write: before a trace (--trace) or a timeline (--timeline) is written, a dry
// run of the model writes neither but counts the bytes each would have, so a file too large is
// refused before any time is spent writing it. The count is exact for VCD and for the timeline;
// an FST is estimated from the VCD's bytes (kVcdBytesPerFstByte, measured: docs/waveforms.md).
// With --trace-ray a first run finds the cycle the ray enters the RTU and the cycle its result
// reaches the host: the window of both files. The model is deterministic, so every run of the
// same input has the same cycles.

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "run/rtu_simulation.h"
#include "sim/rtu_config.h"

namespace rtu {

// The VCD bytes one FST byte stands for, as measured on real traces.
constexpr double kVcdBytesPerFstByte = 9.0;

struct TraceLimits {
  int64_t ray = -1;  // --trace-ray: the window of this job; -1: none
  uint64_t maxBytes = 0;
};

struct TraceSizes {
  uint64_t trace = 0, timeline = 0;  // bytes of each file (of an FST: estimated)
  uint64_t vcd = 0;                  // bytes of the trace as VCD
};

// The bytes of a trace at `path` whose VCD has `vcdBytes`: those, or an FST's estimate.
uint64_t traceFileBytes(const std::string& path, uint64_t vcdBytes);

// Prints the sizes of the trace and the timeline asked for (an empty path: none) and throws
// std::invalid_argument naming the options that narrow a file above limits.maxBytes.
void reportTraceSizes(const TraceSizes& sizes, const std::string& tracePath,
                      const std::string& timelinePath, const TraceLimits& limits,
                      std::ostream& out);

// The window of job `ray`: from its handshake into the job manager to the cycle after its result's
// handshake with the host, and the core that ran it (-1 when no core did: a scene's ray). Throws
// std::invalid_argument for a ray the records do not have.
struct RayWindow {
  uint64_t from = 0, to = 0;
  int core = -1;
};
RayWindow rayWindow(const WordMemory& memory, const std::vector<HostRecord>& records,
                    const RtuConfig& config, uint64_t ray);

// The sizes of the files `config` asks for, from a dry run.
TraceSizes measureTrace(const WordMemory& memory, const std::vector<HostRecord>& records,
                        const RtuConfig& config, const RunProgress& progress);

// `config` with the window of limits.ray; prints the sizes; throws std::invalid_argument naming
// the options that narrow a file above limits.maxBytes.
RtuConfig planTrace(const WordMemory& memory, const std::vector<HostRecord>& records,
                    RtuConfig config, const TraceLimits& limits, std::ostream& out,
                    const RunProgress& progress = {});

}  // namespace rtu
