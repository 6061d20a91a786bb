#include "config/sweep_spec.h"

#include <cstdio>
#include <iostream>
#include <stdexcept>

#include <toml++/toml.h>

#include "base/input_file.h"
#include "base/nesting_depth.h"
#include "rtu/host_memory.h"

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

namespace {

// A point of a sweep as it is held (its configuration's values, sources and maps, its row's
// fields), measured: a 10^4-point grid's dry run (`sweep --slurm --dry-run`) took 12.5 KB a point
// more than a 10^2-point one.
constexpr double kConfigurationBytes = 12800;

// The sweep's configurations are held together (its checks, its rows): their count and memory are
// estimated from the grid before any is made, and refused over this machine's memory.
void checkExpansionFits(const SweepSpec& spec) {
  double count = spec.list.empty() ? 1.0 : static_cast<double>(spec.list.size());
  for (const auto& entry : spec.grid) count *= static_cast<double>(entry.second.size());
  const double bytes = count * kConfigurationBytes;
  const uint64_t available = physicalMemoryBytes();
  if (bytes <= static_cast<double>(available)) return;
  char points[32];
  std::snprintf(points, sizeof points, "%.4g", count);
  throw std::invalid_argument(std::string("the sweep has ") + points +
                              " configurations, which would hold about " + formatGiB(bytes) +
                              " (about 12.8 KB each), more than the " +
                              formatGiB(static_cast<double>(available)) +
                              " of this machine: sweep fewer values, or the grid in parts");
}

}  // namespace

std::vector<Configuration> SweepSpec::expand(const Configuration& base) const {
  checkExpansionFits(*this);
  std::vector<Assignments> points = {{}};
  for (const auto& [key, values] : grid) {
    std::vector<Assignments> next;
    for (const Assignments& point : points)
      for (const std::string& value : values) {
        Assignments extended = point;
        extended.emplace_back(key, value);
        next.push_back(extended);
      }
    points = next;
  }
  const std::vector<Assignments> entries = list.empty() ? std::vector<Assignments>{{}} : list;
  std::vector<Configuration> configurations;
  for (const Assignments& entry : entries)
    for (const Assignments& point : points) {
      Configuration configuration = base;
      for (const auto& [key, value] : entry) configuration.set(key, value, ConfigSource::Sweep);
      for (const auto& [key, value] : point) configuration.set(key, value, ConfigSource::Sweep);
      configurations.push_back(configuration);
    }
  return configurations;
}

void checkSettingsHaveEffect(const std::vector<Configuration>& configurations, unsigned uses,
                             const std::string& command) {
  for (const Setting& setting : configSchema()) {
    size_t given = 0, ineffective = 0;
    ConfigSource from = ConfigSource::Default;
    std::string reason;
    for (const Configuration& configuration : configurations) {
      const ConfigSource source = configuration.source(setting.key);
      if (!givenByUser(setting, source, configuration.values())) continue;
      ++given;
      if (from != ConfigSource::Sweep) from = source;
      const std::string why = whyIneffective(setting, configuration.values(), uses, command);
      if (why.empty()) continue;
      ++ineffective;
      if (reason.empty()) reason = why;
    }
    if (ineffective == 0) continue;
    if (ineffective < given)
      reportIneffective(setting, from, reason, uses,
                        "in " + std::to_string(ineffective) + " of " + std::to_string(given) +
                            " configurations");
    else if (from == ConfigSource::Sweep)
      throw std::invalid_argument(setting.key +
                                  " (sweep) has no effect in any configuration: " + reason);
    else
      reportIneffective(setting, from, reason, uses);
  }
}

}  // namespace rtu
