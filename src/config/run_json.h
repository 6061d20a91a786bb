#pragma once
// A run's result as a file that says how to reproduce it: the statistics beside the whole
// effective configuration and the rtusim version.

#include <nlohmann/json.hpp>

#include "config/configuration.h"
#include "run/rtu_statistics.h"

namespace rtu {

// {"rtusim": {"version"}, "preset": name or "", "config": {every key}, "statistics": {...}}.
nlohmann::ordered_json runJson(const RtuStatistics& statistics, const Configuration& configuration);
// The same around statistics written as JSON already (the ray pipe's:
// raypipe/raypipe_statistics.h).
nlohmann::ordered_json runJson(nlohmann::ordered_json statistics,
                               const Configuration& configuration);

}  // namespace rtu
