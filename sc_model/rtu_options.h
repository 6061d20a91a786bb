#pragma once
// Command-line options of the SystemC RTU model (replay, render), bound to CLI11, and what the
// commands do with a finished run: the report, the --stats JSON.

#include <cstdint>
#include <iosfwd>
#include <limits>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "golden_model.h"
#include "rtu_config.h"
#include "rtu_simulation.h"
#include "svo_image.h"

namespace rtu {

struct RtuOptions {
  RtuConfig config;
  std::string memory = "ideal";
  std::string statsPath;
  std::string vcdPath;
  uint64_t vcdFrom = 0;
  uint64_t vcdTo = std::numeric_limits<uint64_t>::max();
  std::vector<std::string> vcdScopes;
  bool allowStackOverflow = false;

  // The configuration after parsing: memory kind, trace and the golden model's arithmetic.
  RtuConfig resolve(const GoldenConfig& golden) const;
};

void addRtuOptions(CLI::App& command, RtuOptions& options);

// Prints the report and writes the --stats JSON if asked for.
void reportRun(const RtuRun& run, const RtuOptions& options, std::ostream& out);

}  // namespace rtu
