#pragma once
// A run's architecture as hardware (issue 30 §2; docs/comparison.md, "Resources"): the RTU's
// estimate (sim/rtu_resources.h) or the ray pipe's (raypipe/raypipe_resources.h) as the rows of
// fps, sweep and compare carry it ("resources"), with the columns the CSV outputs add.

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "config/run_config.h"
#include "rtu/resource_estimate.h"

namespace rtu {

// The architecture `settings` choose, with `imageWords` the scene's words (held on chip by an
// RTU with ideal memory).
ResourceEstimate architectureResources(const RunConfig& settings, uint64_t imageWords);

// The totals (resourceColumns, in order) and the itemised "memories" and "units".
nlohmann::ordered_json resourcesJson(const ResourceEstimate& estimate);

// memory_bits, bram_bits, bram18k, dsp48e, multipliers, adders, dividers, comparators, luts.
const std::vector<std::string>& resourceColumns();
// A row's "resources" as those columns (empty strings for a row without them).
std::vector<std::string> resourceValues(const nlohmann::ordered_json& row);

// `fps` per `amount` of a resource, or null where the architecture has none of it.
nlohmann::ordered_json perResource(const nlohmann::ordered_json& fps,
                                   const nlohmann::ordered_json& amount);

}  // namespace rtu
