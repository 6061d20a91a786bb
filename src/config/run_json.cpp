#include "config/run_json.h"

namespace rtu {

nlohmann::ordered_json runJson(const RtuStatistics& statistics,
                               const Configuration& configuration) {
  return {{"rtusim", {{"version", rtusimVersion()}}},
          {"preset", configuration.preset()},
          {"config", configuration.toJson()},
          {"statistics", statistics.toJson()}};
}

}  // namespace rtu
