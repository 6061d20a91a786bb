#pragma once
// A deliberately naive cycle model of the thesis RTL top level: appendix C.1 (rtu) with C.2
// (job_manager), C.3 (scheduler), the handshakes of C.4 (svo_trav_core) and C.5
// (result_manager). Every cycle first computes all combinational signals from the registers,
// then updates every register of every module, as the clock edge does. Speed is no concern: it is
// the reference the event-driven SystemC model is checked against, cycle count and result.
//
// The host: cycle 0 is the first cycle after reset. It offers job 0 from cycle 0 and job i + 1
// from the cycle after job i's handshake, and it is ready for a result in every cycle. Memory is
// ideal (data in the cycle of the address), as in the thesis.

#include <cstdint>
#include <vector>

#include "golden_model.h"
#include "svo_memory.h"
#include "traversal_job.h"

namespace rtu {

constexpr int kMaxRtlCores = 4096;

struct RtlTopConfig {
  int cores = 16;  // CORE_CNT
  GoldenConfig golden;

  // Throws std::invalid_argument unless 1 <= cores <= kMaxRtlCores and the golden configuration
  // is valid.
  void validate() const;
};

struct RtlTopRun {
  std::vector<TraversalResult> results;  // in the order the host received them
  std::vector<uint64_t> resultCycles;    // cycle of each result's handshake with the host
  std::vector<uint64_t> acceptCycles;    // per job index: its host -> job manager handshake
  std::vector<uint64_t> dispatchCycles;  // per job index: its scheduler -> core handshake
  uint64_t totalCycles = 0;              // cycle in which the last result was taken, plus one
};

RtlTopRun runRtlTop(const SvoMemory& memory, const std::vector<TraversalJob>& jobs,
                    const RtlTopConfig& config);

}  // namespace rtu
