#pragma once
// One run's effective configuration, built in layers over the schema's defaults: a preset, then
// configuration files (TOML or JSON), then the command line (`--set key=value` and each
// setting's own flag). It remembers where each setting came from, so that a setting a user gave
// and that has no effect is reported instead of silently dropped.

#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "config/config_schema.h"

namespace rtu {

// Sweep: a value a sweep's grid or list gives one of its configurations.
enum class ConfigSource { Default, Preset, File, CommandLine, Sweep };

// Why `setting` has no effect for rtusim `command`, which uses the settings of `uses`
// (SettingUse bits), in the configuration `effective`; empty when it has one.
std::string whyIneffective(const Setting& setting, const RunConfig& effective, unsigned uses,
                           const std::string& command);

// Whether `setting`, from `from` in `values`, is the user's: from the command line, a sweep, or a
// file that states other than the default (a dumped configuration states them all).
bool givenByUser(const Setting& setting, ConfigSource from, const RunConfig& values);

// A setting the user gave from `from` without effect for `reason` ("memory is ideal", in `share`
// of the configurations: "in 2 of 4 configurations", or empty for all): a std::invalid_argument
// for one on the command line that the command does not use or a scene source beside another,
// else a warning on standard error.
void reportIneffective(const Setting& setting, ConfigSource from, const std::string& reason,
                       unsigned uses, const std::string& share = "");

class Configuration {
 public:
  const RunConfig& values() const { return values_; }
  RunConfig& values() { return values_; }

  // Throws std::invalid_argument naming the key (and the nearest key when unknown).
  void set(const std::string& key, const std::string& text, ConfigSource source);
  // "key=value".
  void setAssignment(const std::string& assignment, ConfigSource source);
  // Also remembers the preset's name, which a run's JSON records beside its configuration.
  void applyPreset(const std::string& name);
  const std::string& preset() const { return preset_; }
  // .toml or .json, nested tables or dotted keys; errors name the file. A .json statistics file
  // (`--stats`) is read as its "config" object, the configuration of its run.
  void loadFile(const std::string& path);
  void loadText(const std::string& text, const std::string& format, const std::string& origin,
                ConfigSource source);

  ConfigSource source(const std::string& key) const;
  // Settings given in a file or on the command line that the command (its `uses`) or this
  // configuration ignores: errors for the command line and for scene sources given together,
  // warnings on standard error for files. `commandSets`, if given, applies what the command
  // sets itself (fidelity samples at its own fractions) before asking which settings are ignored.
  void checkApplicable(unsigned uses, const std::string& command,
                       const std::function<void(RunConfig&)>& commandSets = {}) const;

  // The whole configuration, loadable again with --config.
  std::string toToml() const;
  // Flat: key -> typed value, in schema order.
  nlohmann::ordered_json toJson() const;

 private:
  RunConfig values_;
  std::map<std::string, ConfigSource> sources_;
  std::string preset_;  // empty: none
};

// Shipped presets (presets/*.toml, embedded in the binary).
std::vector<std::string> presetNames();
// Throws std::invalid_argument naming the presets for an unknown name.
const std::string& presetText(const std::string& name);

// The rtusim version: project version and source revision.
const char* rtusimVersion();

}  // namespace rtu
