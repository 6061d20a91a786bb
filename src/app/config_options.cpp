#include "app/config_options.h"

namespace rtu {

Configuration ConfigRequest::resolve() const {
  Configuration configuration;
  if (!preset.empty()) configuration.applyPreset(preset);
  for (const std::string& file : files) configuration.loadFile(file);
  for (const auto& [key, text] : flags) configuration.set(key, text, ConfigSource::CommandLine);
  for (const std::string& assignment : assignments)
    configuration.setAssignment(assignment, ConfigSource::CommandLine);
  configuration.checkApplicable(uses, command, commandSets);
  return configuration;
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
  command.add_option("--config", request->files, "configuration file(s), TOML or JSON, applied in order")
      ->check(CLI::ExistingFile)
      ->group("Configuration");
  command.add_option("--set", request->assignments,
                     "key=value for any setting (rtusim config --list), applied last")
      ->group("Configuration");
  const RunConfig defaults;
  for (const Setting& setting : configSchema()) {
    if (!(setting.uses & uses) || setting.flag.empty() || skipFlags.count(setting.flag)) continue;
    // Two settings share a spelling only where no command but `config` uses both (--epsilon
    // of ray records and of the camera): the first one declared keeps it.
    if (command.get_option_no_throw(setting.flag)) continue;
    std::string help = setting.doc + " [" + setting.key;
    if (!setting.unit.empty()) help += ", " + setting.unit;
    const std::string value = setting.get(defaults);
    if (!value.empty()) help += ", default " + value;
    help += "]";
    const std::string key = setting.key;
    if (setting.kind == SettingKind::Flag) {
      command.add_flag_callback(setting.flag, [request, key] { request->flags.emplace_back(key, "true"); },
                                help);
    } else {
      command.add_option_function<std::string>(
          setting.flag, [request, key](const std::string& text) { request->flags.emplace_back(key, text); },
          help);
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
