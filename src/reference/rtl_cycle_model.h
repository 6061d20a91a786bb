#pragma once
// A deliberately naive cycle model of the thesis RTL top level: appendix C.1 (rtu) with C.2
// (job_manager), C.3 (scheduler), the handshakes of C.4 (svo_trav_core) and C.5
// (result_manager). Every cycle first computes all combinational signals from the registers,
// then updates every register of every module, as the clock edge does. Speed is no concern: it is
// the reference the event-driven SystemC model is checked against, cycle count and result.
//
// The job manager also takes ray records (the kind's Setup), as the SystemC one does: a
// ray passes `rayStages` more stages and, the first against a model, waits `headerFetchCycles` for
// its header, in which no record is accepted (docs/cycle-semantics.md "Job manager").
//
// runRtlTop is the thesis' host: cycle 0 is the first cycle after reset. It offers job 0 from
// cycle 0 and job i + 1 from the cycle after job i's handshake, and it is ready for a result in
// every cycle. Another host (the scene manager's reference, src/reference/scene_manager_cycles.h)
// steps the registers itself (RtlTop<Kind>, src/reference/rtl_top.h: a template over the cores'
// kind, chosen once by the host with withCoreKind). Memory is ideal (data in the cycle of the
// address), as in the thesis.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "kinds/registry.h"
#include "kinds/svo/svo_kind.h"
#include "kinds/svo/thesis_records.h"
#include "rtu/word_memory.h"

namespace rtu {

constexpr int kMaxRtlCores = 4096;

struct RtlTopConfig {
  int cores = 16;                     // CORE_CNT
  CoreKindConfigs coreConfigs;        // every kind's own settings (kinds/registry.h)
  int rayStages = 6;                  // beyond P_STAGES, for ray records
  int headerFetchCycles = 16;         // a model's first ray
  std::string core = SvoKind::kName;  // the cores' kind (kinds/registry.h)
  // Cores per ray/triangle unit (core.triangle.shared_by), for a kind with one; round-robin.
  int triangleSharedBy = 1;

  // Throws std::invalid_argument unless 1 <= cores <= kMaxRtlCores, every kind's settings are
  // valid, 0 <= rayStages <= 64, headerFetchCycles >= 0 and 1 <= triangleSharedBy <= cores.
  void validate() const;
  // The settings of a core of `Kind`, as RtuConfig's.
  template <class Kind>
  const typename Kind::Config& coreConfig() const {
    return CoreKinds::configOf<Kind>(coreConfigs);
  }
  template <class Kind>
  typename Kind::Config& coreConfig() {
    return CoreKinds::configOf<Kind>(coreConfigs);
  }
};

struct RtlTopRun {
  std::vector<CoreKindResult> results;   // in the order the host received them
  std::vector<uint64_t> resultCycles;    // cycle of each result's handshake with the host
  std::vector<uint64_t> acceptCycles;    // per job index: its host -> job manager handshake
  std::vector<uint64_t> dispatchCycles;  // per job index: its scheduler -> core handshake
  uint64_t totalCycles = 0;              // cycle in which the last result was taken, plus one
};

RtlTopRun runRtlTop(const WordMemory& memory, const std::vector<HostRecord>& records,
                    const RtlTopConfig& config);
RtlTopRun runRtlTop(const WordMemory& memory, const std::vector<TValueRecord>& jobs,
                    const RtlTopConfig& config);

// What a host offers the job manager in one cycle; `tag` names the job to the host (no RTL
// signal: the result comes back with it).
struct RtlOffer {
  HostRecord record;
  uint64_t tag = 0;
};

// The handshakes of one cycle with a host that is ready for a result in every cycle.
struct RtlCycle {
  uint64_t cycle = 0;
  bool accepted = false;  // the offer was taken
  struct Delivery {
    CoreKindResult result;  // of the cores' kind
    uint64_t tag = 0;
  };
  std::optional<Delivery> delivered;  // the result the host took
};

}  // namespace rtu
