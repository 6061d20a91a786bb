#include "config/run_json.h"

#include <utility>

namespace rtu {

nlohmann::ordered_json runJson(const RtuStatistics& statistics,
                               const Configuration& configuration) {
  return runJson(statistics.toJson(), configuration);
}

nlohmann::ordered_json runJson(nlohmann::ordered_json statistics,
                               const Configuration& configuration) {
  return {{"rtusim", {{"version", rtusimVersion()}}},
          {"preset", configuration.preset()},
          {"config", configuration.toJson()},
          {"statistics", std::move(statistics)}};
}

}  // namespace rtu
