#pragma once
// The ranges of clock, rates and latencies the timing arithmetic supports, checked before a run
// (validate() of each configuration, and the configuration schema's ranges derive from these).
// Within them nothing overflows: cycle counts are uint64, SystemC time is a uint64 count of
// picoseconds, and a transfer of the longest line at the slowest rate takes
// 65536 / 1e-3 = 6.6e7 cycles.

#include <cstdint>
#include <string>

namespace rtu {

// Clock in MHz. The period (1e6 / MHz ps) is rounded to SystemC's 1 ps resolution: at 1 THz it is
// 1 ps; at 1 MHz 1e6 ps, so 2^64 ps hold 1.8e13 cycles, past kMaxCycles.
constexpr double kMinClockMhz = 1.0;
constexpr double kMaxClockMhz = 1e6;

// The last cycle a run may reach; CycleClock refuses to schedule past it.
constexpr uint64_t kMaxCycles = 10'000'000'000'000ull;  // 1e13

// DRAM bus and host links. Below 1e-3 bytes a cycle, transfer times leave uint64 (1e-18 wrapped
// to a fast bus before this limit existed).
constexpr double kMinBytesPerCycle = 1e-3;
constexpr double kMaxBytesPerCycle = 1e6;
inline std::string rateRange() { return "[0.001, 1000000] bytes per cycle"; }

// Cache hit, DRAM and model-header latencies.
constexpr uint32_t kMaxLatencyCycles = 1'000'000;

}  // namespace rtu
