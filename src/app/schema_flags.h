#pragma once
// The configuration schema on the command line: `--preset NAME`, `--config FILE` (repeatable),
// `--set key=value` (repeatable) and every setting's own flag (`--cores 4` is `--set cores=4`),
// for the settings a command uses.

#include <functional>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "config/configuration.h"

namespace rtu {

struct ConfigRequest {
  std::string command;  // for messages: "replay"
  unsigned uses = 0;    // SettingUse bits
  std::string preset;
  std::vector<std::string> files;
  std::vector<std::pair<std::string, std::string>> flags;  // key, text
  std::vector<std::string> assignments;                    // --set key=value
  std::function<void(RunConfig&)> commandSets;  // what the command sets itself, if anything

  // Defaults, then the preset, the files, the flags and --set; then checks that every setting the
  // user gave has an effect (see Configuration::checkApplicable).
  Configuration resolve() const;
  // The same without the check, for a command that checks its configurations together (a sweep:
  // checkSettingsHaveEffect). Both refuse architecture = raypipe as checkArchitectureRuns does.
  Configuration resolveUnchecked() const;
};

// Throws std::invalid_argument for architecture = raypipe in a command (of settings `uses`) that
// runs only the RTU: every one that runs a model but render, fps, sweep and fidelity (and config,
// which runs none).
void checkArchitectureRuns(const Configuration& configuration, const std::string& command,
                           unsigned uses);

// Registers the options; `skipFlags` are flags the command spells itself (fps takes a list for
// --cores). The request must outlive parsing.
std::shared_ptr<ConfigRequest> addConfigOptions(CLI::App& command, unsigned uses,
                                                const std::set<std::string>& skipFlags = {});

// For replay and golden: an SVO image and exactly one of jobs and rays.
void checkOneInputBuffer(const RunConfig& settings);

}  // namespace rtu
