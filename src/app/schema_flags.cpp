#include "app/schema_flags.h"

#include <iostream>

#include "app/input_file_check.h"

namespace rtu {
namespace {

// The option `names` ("--ray-epsilon,--epsilon") for `setting`; `warning`, if any, goes to
// standard error when it is given.
CLI::Option* addSettingOption(CLI::App& command, const std::shared_ptr<ConfigRequest>& request,
                              const Setting& setting, const std::string& names,
                              const std::string& help, const std::string& warning = "") {
  const std::string key = setting.key;
  if (setting.kind == SettingKind::Flag) {
    return command.add_flag_callback(
        names,
        [request, key, warning] {
          if (!warning.empty()) std::cerr << warning << "\n";
          request->flags.emplace_back(key, "true");
        },
        help);
  }
  return command.add_option_function<std::string>(
      names,
      [request, key, warning](const std::string& text) {
        if (!warning.empty()) std::cerr << warning << "\n";
        request->flags.emplace_back(key, text);
      },
      help);
}

}  // namespace

Configuration ConfigRequest::resolve() const {
  Configuration configuration = resolveUnchecked();
  configuration.checkApplicable(uses, command, commandSets);
  return configuration;
}

Configuration ConfigRequest::resolveUnchecked() const {
  Configuration configuration;
  if (!preset.empty()) configuration.applyPreset(preset);
  for (const std::string& file : files) configuration.loadFile(file);
  for (const auto& [key, text] : flags) configuration.set(key, text, ConfigSource::CommandLine);
  for (const std::string& assignment : assignments)
    configuration.setAssignment(assignment, ConfigSource::CommandLine);
  checkArchitectureRuns(configuration, command, uses);
  return configuration;
}

void checkArchitectureRuns(const Configuration& configuration, const std::string& command,
                           unsigned uses) {
  // The commands that run the ray pipe (docs/raypipe.md); the others would run the RTU in its
  // place.
  static const std::set<std::string> runPipe = {"render", "fps", "sweep", "fidelity", "config"};
  const bool runsArchitecture = (uses & (kUseModel | kUseArithmetic)) != 0;
  if (configuration.values().architecture == Architecture::Raypipe && runsArchitecture &&
      !runPipe.count(command))
    throw std::invalid_argument("architecture = raypipe: rtusim " + command +
                                " runs the RTU only; seed 001's ray pipe runs in rtusim render, "
                                "fps, sweep and fidelity (docs/raypipe.md)");
}

std::shared_ptr<ConfigRequest> addConfigOptions(CLI::App& command, unsigned uses,
                                                const std::set<std::string>& skipFlags) {
  auto request = std::make_shared<ConfigRequest>();
  request->command = command.get_name();
  request->uses = uses;
  std::string presets;
  for (const std::string& name : presetNames()) presets += (presets.empty() ? "" : ", ") + name;
  command.add_option("--preset", request->preset, "start from a shipped preset: " + presets)
      ->check(CLI::IsMember(presetNames()))
      ->group("Configuration");
  command
      .add_option("--config", request->files,
                  "configuration file(s), TOML or JSON, applied in order")
      ->check(regularInputFile())
      ->group("Configuration");
  command
      .add_option("--set", request->assignments,
                  "key=value for any setting (rtusim config --list), applied last")
      ->group("Configuration");
  const RunConfig defaults;
  const std::vector<Setting>& schema = configSchema();
  const auto takes = [&](const Setting& s) {
    return (s.uses & uses) && !s.flag.empty() && !skipFlags.count(s.flag);
  };
  for (const Setting& setting : schema) {
    if (!takes(setting)) continue;
    std::string help = setting.doc + " [" + setting.key;
    if (!setting.unit.empty()) help += ", " + setting.unit;
    const std::string value = setting.get(defaults);
    if (!value.empty()) help += ", default " + value;
    help += "]";
    // A former spelling (--epsilon) is an alias where this is the command's only setting of that
    // spelling; where several share it, it keeps the first one's meaning, with a warning.
    std::vector<const Setting*> sharing;
    if (!setting.formerFlag.empty())
      for (const Setting& other : schema)
        if (takes(other) && other.formerFlag == setting.formerFlag) sharing.push_back(&other);
    addSettingOption(command, request, setting,
                     sharing.size() == 1 ? setting.flag + "," + setting.formerFlag : setting.flag,
                     help);
    if (sharing.size() > 1 && sharing.front() == &setting) {
      std::string instead;
      for (const Setting* other : sharing)
        instead += (instead.empty() ? "" : " or ") + other->flag + " (" + other->key + ")";
      const std::string warning = "rtusim: warning: " + setting.formerFlag +
                                  " is ambiguous in rtusim " + request->command +
                                  " and deprecated: it sets " + setting.key + ", as " +
                                  setting.flag + " does; use " + instead;
      addSettingOption(command, request, setting, setting.formerFlag,
                       "deprecated: as " + setting.flag + "; use " + instead, warning)
          ->group("Deprecated");
    }
  }
  return request;
}

void checkOneInputBuffer(const RunConfig& settings) {
  if (settings.scene.svoFile.empty()) throw std::invalid_argument("give the SVO image: --svo FILE");
  if (!settings.jobs.empty() && !settings.rays.empty())
    throw std::invalid_argument("jobs excludes rays: give one input buffer");
  if (settings.jobs.empty() && settings.rays.empty())
    throw std::invalid_argument("give the input: --jobs (job records) or --rays (ray records)");
}

}  // namespace rtu
