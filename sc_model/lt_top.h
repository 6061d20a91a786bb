#pragma once
// The loosely-timed RTU (docs/fidelity.md, "The loosely-timed model"): thesis figure 6.1 at
// transaction level. N traversal cores, TLM-2.0 initiators with temporal decoupling, take jobs
// from the dispatcher (job manager and scheduler) and hand results to the collector (result
// manager and output link); their memory is the ideal ROM (DMI) or, per core, an L1 target in
// front of the shared L2 target and the DRAM target.

#include <memory>
#include <vector>

#include "cache_contents.h"
#include "lt_dispatcher.h"
#include "lt_dram.h"
#include "lt_l1_cache.h"
#include "lt_l2_cache.h"
#include "lt_result_collector.h"
#include "lt_rom.h"
#include "lt_traversal_core.h"
#include "rtu_config.h"

namespace rtu {

class LtTop : public sc_core::sc_module {
 public:
  // `records` must outlive the top. `startCaches`: lines resident from cycle 0, or null.
  LtTop(sc_core::sc_module_name name, const RtuConfig& config, SvoMemory memory,
        const std::vector<HostRecord>& records, const CacheContents* startCaches = nullptr);

  const LtDispatcher& dispatcher() const { return *dispatcher_; }
  const LtResultCollector& collector() const { return *collector_; }
  bool idealMemory() const { return rom_ != nullptr; }
  std::vector<CacheStats> l1Statistics() const;
  L2Stats l2Statistics() const;  // the L2's counts with the DRAM target's

 private:
  void bindCachedMemory(const RtuConfig& config, SvoMemory memory, const CacheContents* start);

  LtTime time_;
  std::unique_ptr<LtDispatcher> dispatcher_;
  std::unique_ptr<LtResultCollector> collector_;
  std::vector<std::unique_ptr<LtTraversalCore>> cores_;
  std::unique_ptr<LtRom> rom_;
  std::vector<std::unique_ptr<LtL1Cache>> l1_;
  std::unique_ptr<LtL2Cache> l2_;
  std::unique_ptr<LtDram> dram_;
};

}  // namespace rtu
