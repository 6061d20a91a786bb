#include "config/sweep_spec.h"

#include <cstdio>
#include <iostream>
#include <stdexcept>

#include <toml++/toml.h>

#include "base/input_file.h"
#include "base/nesting_depth.h"

namespace rtu {
namespace {

std::string leafText(const toml::node& node, const std::string& key) {
  if (const auto* s = node.as_string()) return s->get();
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  if (const auto* b = node.as_boolean()) return b->get() ? "true" : "false";
  if (const auto* f = node.as_floating_point()) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", f->get());
    return text;
  }
  throw std::invalid_argument("sweep key " + key + ": values must be numbers, strings or booleans");
}

// Flattens nested tables to dotted keys, calling `leaf` for every non-table value.
template <class Leaf>
void flatten(const toml::table& table, const std::string& prefix, const Leaf& leaf) {
  for (const auto& [name, node] : table) {
    const std::string key = prefix.empty() ? std::string(name.str())
                                           : prefix + "." + std::string(name.str());
    if (const auto* sub = node.as_table())
      flatten(*sub, key, leaf);
    else
      leaf(key, node);
  }
}

// Every value must be one its key accepts, so that a bad value is an error naming the file
// rather than a failure of the expansion later.
void checkValues(const SweepSpec& spec) {
  Configuration probe;
  for (const auto& [key, values] : spec.grid)
    for (const std::string& value : values) probe.set(key, value, ConfigSource::File);
  for (const SweepSpec::Assignments& entry : spec.list)
    for (const auto& [key, value] : entry) probe.set(key, value, ConfigSource::File);
}

}  // namespace

void SweepSpec::addGrid(const std::string& argument) {
  const size_t equals = argument.find('=');
  if (equals == std::string::npos || equals == 0 || equals + 1 == argument.size())
    throw std::invalid_argument("--grid takes key=v1,v2,..., got '" + argument + "'");
  const std::string key = findSetting(argument.substr(0, equals)).key;
  std::vector<std::string> values;
  size_t start = equals + 1;
  for (size_t comma; (comma = argument.find(',', start)) != std::string::npos; start = comma + 1)
    values.push_back(argument.substr(start, comma - start));
  values.push_back(argument.substr(start));
  grid.emplace_back(key, values);
}

void SweepSpec::loadFile(const std::string& path) {
  try {
    const std::string text = readInputFile(path, "sweep file", kMaxSettingsFileBytes);
    checkTomlNesting(text);
    const toml::table file = toml::parse(text, path);
    for (const auto& [name, node] : file) {
      const std::string section(name.str());
      if (section == "grid" && node.is_table()) {
        flatten(*node.as_table(), "", [this](const std::string& key, const toml::node& values) {
          std::vector<std::string> texts;
          if (const auto* array = values.as_array()) {
            for (const toml::node& value : *array) texts.push_back(leafText(value, key));
          } else {
            texts.push_back(leafText(values, key));
          }
          grid.emplace_back(findSetting(key).key, texts);
        });
      } else if (section == "configs" && node.is_array_of_tables()) {
        for (const toml::node& entry : *node.as_array()) {
          Assignments assignments;
          flatten(*entry.as_table(), "",
                  [&assignments](const std::string& key, const toml::node& value) {
                    assignments.emplace_back(findSetting(key).key, leafText(value, key));
                  });
          list.push_back(assignments);
        }
      } else {
        throw std::invalid_argument("unknown section '" + section +
                                    "' (a sweep file has [grid] and [[configs]])");
      }
    }
    checkValues(*this);
  } catch (const toml::parse_error& error) {
    throw std::invalid_argument("sweep file '" + path + "': " + std::string(error.description()));
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument("sweep file '" + path + "': " + error.what());
  } catch (const std::runtime_error& error) {  // from readInputFile, naming the file
    throw std::invalid_argument(error.what());
  }
}

SettingsEffectCheck::SettingsEffectCheck(unsigned uses, std::string command)
    : uses_(uses), command_(std::move(command)), tallies_(configSchema().size()) {}

void SettingsEffectCheck::add(const Configuration& configuration) {
  const std::vector<Setting>& schema = configSchema();
  for (size_t s = 0; s < schema.size(); ++s) {
    const Setting& setting = schema[s];
    const ConfigSource source = configuration.source(setting.key);
    if (!givenByUser(setting, source, configuration.values())) continue;
    Tally& tally = tallies_[s];
    ++tally.given;
    if (tally.from != ConfigSource::Sweep) tally.from = source;
    const std::string why = whyIneffective(setting, configuration.values(), uses_, command_);
    if (why.empty()) continue;
    ++tally.ineffective;
    if (tally.reason.empty()) tally.reason = why;
  }
}

void SettingsEffectCheck::finish() const {
  const std::vector<Setting>& schema = configSchema();
  for (size_t s = 0; s < schema.size(); ++s) {
    const Setting& setting = schema[s];
    const Tally& tally = tallies_[s];
    if (tally.ineffective == 0) continue;
    if (tally.ineffective < tally.given)
      reportIneffective(setting, tally.from, tally.reason, uses_,
                        "in " + std::to_string(tally.ineffective) + " of " +
                            std::to_string(tally.given) + " configurations");
    else if (tally.from == ConfigSource::Sweep)
      throw std::invalid_argument(setting.key +
                                  " (sweep) has no effect in any configuration: " + tally.reason);
    else
      reportIneffective(setting, tally.from, tally.reason, uses_);
  }
}

void checkSettingsHaveEffect(const std::vector<Configuration>& configurations, unsigned uses,
                             const std::string& command) {
  SettingsEffectCheck check(uses, command);
  for (const Configuration& configuration : configurations) check.add(configuration);
  check.finish();
}

}  // namespace rtu
