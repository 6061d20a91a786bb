#include "sim/ca/timed_core.h"

namespace rtu {

std::unique_ptr<TimedCoreBase> makeTimedCore(const RtuConfig& config, const char* name,
                                             DecisionPump& pump, int index, CycleTrace* trace) {
  return withCoreKind(config.core, [&](auto kind) -> std::unique_ptr<TimedCoreBase> {
    using Kind = decltype(kind);
    return std::make_unique<TimedCore<Kind>>(name, pump, index, config.coreConfig<Kind>(), trace);
  });
}

}  // namespace rtu
