#include "config/configuration.h"

#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include <toml++/toml.h>

#include "base/input_file.h"
#include "base/nesting_depth.h"
#include "embedded_presets.h"
#include "rtusim_version.h"

namespace rtu {
namespace {

std::string join(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

std::string realText(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// A TOML leaf as the text Setting::assign reads: numbers, strings, booleans, [x, y, z].
// An array is the x, y, z of a vector setting; given to another (`cores = [4]`) it was read as
// its elements joined by commas, so one element passed as the value.
void requireVectorSetting(const std::string& key) {
  if (findSetting(key).kind != SettingKind::Vector)
    throw std::invalid_argument(key + ": an array is given where the setting takes one value");
}

std::string tomlLeafText(const toml::node& node, const std::string& key) {
  if (const auto* s = node.as_string()) return s->get();
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  if (const auto* f = node.as_floating_point()) return realText(f->get());
  if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
  if (const auto* a = node.as_array()) {
    requireVectorSetting(key);
    std::string text;
    for (const toml::node& element : *a)
      text += (text.empty() ? "" : ",") + tomlLeafText(element, key);
    return text;
  }
  throw std::invalid_argument(key + ": unsupported value type");
}

void flattenToml(const toml::table& table, const std::string& prefix,
                 std::vector<std::pair<std::string, std::string>>& out) {
  for (const auto& [name, node] : table) {
    const std::string key = join(prefix, std::string(name.str()));
    if (const auto* sub = node.as_table())
      flattenToml(*sub, key, out);
    else
      out.emplace_back(key, tomlLeafText(node, key));
  }
}

std::string jsonLeafText(const nlohmann::json& value, const std::string& key) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_number_integer()) return value.dump();
  if (value.is_number()) return realText(value.get<double>());
  if (value.is_array()) {
    requireVectorSetting(key);
    std::string text;
    for (const auto& element : value)
      text += (text.empty() ? "" : ",") + jsonLeafText(element, key);
    return text;
  }
  throw std::invalid_argument(key + ": unsupported value type");
}

void flattenJson(const nlohmann::json& object, const std::string& prefix,
                 std::vector<std::pair<std::string, std::string>>& out) {
  for (const auto& [name, value] : object.items()) {
    const std::string key = join(prefix, name);
    if (value.is_object())
      flattenJson(value, key, out);
    else
      out.emplace_back(key, jsonLeafText(value, key));
  }
}

// Inserts `value` under the dotted key; where a prefix is already a value (`scene` and
// `scene.depth`), the rest of the key is written as one quoted key at that level.
void insertNested(toml::table& root, const std::string& key, toml::node&& value) {
  toml::table* table = &root;
  size_t start = 0;
  for (size_t dot = key.find('.'); dot != std::string::npos; dot = key.find('.', start)) {
    const std::string part = key.substr(start, dot - start);
    toml::node* existing = table->get(part);
    if (existing && !existing->is_table()) break;
    if (!existing) table->insert(part, toml::table{});
    table = table->get(part)->as_table();
    start = dot + 1;
  }
  table->insert(key.substr(start), std::move(value));
}

std::string sourceName(ConfigSource source) {
  switch (source) {
    case ConfigSource::Default: return "default";
    case ConfigSource::Preset: return "preset";
    case ConfigSource::File: return "configuration file";
    case ConfigSource::CommandLine: return "command line";
    case ConfigSource::Sweep: return "sweep";
  }
  return "?";
}

bool isSceneSource(const std::string& key) {
  return key == "scene" || key == "svo" || key == "mesh" || key == "binvox";
}

}  // namespace

void Configuration::set(const std::string& key, const std::string& text, ConfigSource source) {
  const Setting& setting = findSetting(key);
  setting.assign(values_, text);
  sources_[setting.key] = source;
}

void Configuration::setAssignment(const std::string& assignment, ConfigSource source) {
  const size_t equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0)
    throw std::invalid_argument("--set takes key=value, got '" + assignment + "'");
  set(assignment.substr(0, equals), assignment.substr(equals + 1), source);
}

void Configuration::applyPreset(const std::string& name) {
  loadText(presetText(name), "toml", "preset '" + name + "'", ConfigSource::Preset);
  preset_ = name;
}

void Configuration::loadFile(const std::string& path) {
  std::string text;
  try {
    text = readInputFile(path, "configuration file", kMaxSettingsFileBytes);
  } catch (const std::runtime_error& error) {
    throw std::invalid_argument(error.what());
  }
  const bool json = path.size() >= 5 && path.compare(path.size() - 5, 5, ".json") == 0;
  loadText(text, json ? "json" : "toml", "'" + path + "'", ConfigSource::File);
}

void Configuration::loadText(const std::string& text, const std::string& format,
                             const std::string& origin, ConfigSource source) {
  std::vector<std::pair<std::string, std::string>> entries;
  try {
    if (format == "json") {
      checkJsonNesting(text);
      const nlohmann::json json = nlohmann::json::parse(text);
      // A statistics file (--stats of render or replay, a sweep row) holds its run's configuration
      // as its "config" object, which no setting's key starts: it reruns that run.
      const bool statistics =
          json.is_object() && json.contains("config") && json["config"].is_object();
      flattenJson(statistics ? json["config"] : json, "", entries);
    } else {
      checkTomlNesting(text);
      flattenToml(toml::parse(text, origin), "", entries);
    }
    for (const auto& [key, value] : entries) set(key, value, source);
  } catch (const toml::parse_error& error) {
    std::ostringstream where;
    where << error.source().begin;
    throw std::invalid_argument(origin + ": " + std::string(error.description()) + " at " +
                                where.str());
  } catch (const nlohmann::json::exception& error) {
    throw std::invalid_argument(origin + ": " + error.what());
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(origin + ": " + error.what());
  }
}

ConfigSource Configuration::source(const std::string& key) const {
  const auto found = sources_.find(key);
  return found == sources_.end() ? ConfigSource::Default : found->second;
}

std::string whyIneffective(const Setting& setting, const RunConfig& effective, unsigned uses,
                           const std::string& command) {
  if (!(setting.uses & uses)) return "rtusim " + command + " does not use it";
  return setting.ignoredBecause ? setting.ignoredBecause(effective) : "";
}

bool givenByUser(const Setting& setting, ConfigSource from, const RunConfig& values) {
  if (from == ConfigSource::CommandLine || from == ConfigSource::Sweep) return true;
  return from == ConfigSource::File && setting.get(values) != setting.get(RunConfig{});
}

void reportIneffective(const Setting& setting, ConfigSource from, const std::string& reason,
                       unsigned uses, const std::string& share) {
  const std::string message = setting.key + " (" + sourceName(from) + ") has no effect" +
                              (share.empty() ? "" : " " + share) + ": " + reason;
  const bool sceneConflict =
      isSceneSource(setting.key) && reason.find(" is given") != std::string::npos;
  if (share.empty() && from == ConfigSource::CommandLine &&
      (sceneConflict || !(setting.uses & uses)))
    throw std::invalid_argument(message);
  std::cerr << "rtusim: warning: " << message << "\n";
}

void Configuration::checkApplicable(unsigned uses, const std::string& command,
                                    const std::function<void(RunConfig&)>& commandSets) const {
  RunConfig effective = values_;
  if (commandSets) commandSets(effective);
  for (const Setting& setting : configSchema()) {
    const ConfigSource from = source(setting.key);
    if (from == ConfigSource::Sweep || !givenByUser(setting, from, values_)) continue;
    const std::string reason = whyIneffective(setting, effective, uses, command);
    if (!reason.empty()) reportIneffective(setting, from, reason, uses);
  }
}

std::string Configuration::toToml() const {
  toml::table root;
  for (const Setting& setting : configSchema()) {
    const std::string text = setting.get(values_);
    switch (setting.kind) {
      case SettingKind::Integer:
        insertNested(root, setting.key, toml::value<int64_t>(std::stoll(text)));
        break;
      case SettingKind::Real:
        insertNested(root, setting.key, toml::value<double>(std::stod(text)));
        break;
      case SettingKind::Flag:
        insertNested(root, setting.key, toml::value<bool>(text == "true"));
        break;
      default: insertNested(root, setting.key, toml::value<std::string>(text)); break;
    }
  }
  std::ostringstream out;
  out << "# rtusim " << rtusimVersion() << " configuration; load it with --config FILE\n"
      << root << "\n";
  return out.str();
}

nlohmann::ordered_json Configuration::toJson() const {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  for (const Setting& setting : configSchema()) {
    const std::string text = setting.get(values_);
    switch (setting.kind) {
      case SettingKind::Integer: json[setting.key] = std::stoll(text); break;
      case SettingKind::Real: json[setting.key] = std::stod(text); break;
      case SettingKind::Flag: json[setting.key] = text == "true"; break;
      default: json[setting.key] = text; break;
    }
  }
  return json;
}

std::vector<std::string> presetNames() {
  std::vector<std::string> names;
  for (const auto& [name, text] : embeddedPresets()) names.push_back(name);
  return names;
}

const std::string& presetText(const std::string& name) {
  const auto& presets = embeddedPresets();
  const auto found = presets.find(name);
  if (found != presets.end()) return found->second;
  std::string all;
  for (const auto& [known, text] : presets) all += (all.empty() ? "" : ", ") + known;
  throw std::invalid_argument("unknown preset '" + name + "' (presets: " + all + ")");
}

const char* rtusimVersion() { return kRtusimVersion; }

}  // namespace rtu
