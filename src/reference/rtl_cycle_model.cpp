#include "reference/rtl_cycle_model.h"

#include <optional>
#include <stdexcept>
#include <string>

#include "kinds/registry.h"
#include "reference/rtl_top.h"

namespace rtu {

void RtlTopConfig::validate() const {
  if (cores < 1 || cores > kMaxRtlCores)
    throw std::invalid_argument("core count must be 1 to " + std::to_string(kMaxRtlCores) +
                                ", got " + std::to_string(cores));
  CoreKinds::validateConfigs(coreConfigs);
  if (rayStages < 0 || rayStages > 64 || headerFetchCycles < 0)
    throw std::invalid_argument("ray stages must be 0 to 64 and header fetch cycles not negative, "
                                "got " +
                                std::to_string(rayStages) + " and " +
                                std::to_string(headerFetchCycles));
  if (triangleSharedBy < 1 || triangleSharedBy > cores)
    throw std::invalid_argument("core.triangle.shared_by must be 1 to the core count (" +
                                std::to_string(cores) + "), got " +
                                std::to_string(triangleSharedBy));
}

namespace {

// The thesis' host: job i + 1 offered from the cycle after job i was taken.
template <class Kind>
RtlTopRun runTop(const WordMemory& memory, const std::vector<HostRecord>& records,
                 const RtlTopConfig& config) {
  RtlTop<Kind> top(memory, config);
  RtlTopRun run;
  size_t next = 0;
  while (run.results.size() < records.size()) {
    std::optional<RtlOffer> offer;
    if (next < records.size()) offer = RtlOffer{records[next], next};
    const RtlCycle cycle = top.step(offer ? &*offer : nullptr);
    if (cycle.accepted) ++next;
    if (cycle.delivered) {
      run.results.push_back(cycle.delivered->result);
      run.resultCycles.push_back(cycle.cycle);
    }
  }
  run.acceptCycles = top.acceptCycles();
  run.dispatchCycles = top.dispatchCycles();
  run.totalCycles = top.cycle();
  return run;
}

}  // namespace

// The kind chosen once: every cycle below is RtlTop<Kind>'s, with no virtual call.
RtlTopRun runRtlTop(const WordMemory& memory, const std::vector<HostRecord>& records,
                    const RtlTopConfig& config) {
  checkCoreTakes(config.core, records);
  return withCoreKind(config.core,
                      [&](auto kind) { return runTop<decltype(kind)>(memory, records, config); });
}

RtlTopRun runRtlTop(const WordMemory& memory, const std::vector<TValueRecord>& jobs,
                    const RtlTopConfig& config) {
  return runRtlTop(memory, std::vector<HostRecord>(jobs.begin(), jobs.end()), config);
}

}  // namespace rtu
