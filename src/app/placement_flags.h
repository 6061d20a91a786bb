#pragma once
// Command-line options of an animated model's placement, bound to CLI11. Every other setting
// comes from the configuration schema (schema_flags.h).

#include <CLI/CLI.hpp>

#include "rtu/model_header.h"

namespace rtu {

// --translate, --rotate-deg and --scale of an animated model, each needing `enabledBy`.
void addPlacementOptions(CLI::App& command, ModelPlacement& placement, glm::dvec3& rotationDegrees,
                         CLI::Option* enabledBy);

// For unsigned options: CLI11 reads "-5" as 2^64 - 5 (--vcd-from -5 ran with a wrapped value).
extern const CLI::Validator kNotNegative;

}  // namespace rtu
