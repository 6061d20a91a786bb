#pragma once
// What a sweep runs: a grid (the cartesian product of value lists over schema keys) and/or an
// explicit list of configurations, each on top of the base configuration (preset, files, flags).
// With both, every listed configuration is combined with every grid point.

#include <string>
#include <utility>
#include <vector>

#include "config/configuration.h"

namespace rtu {

struct SweepSpec {
  using Assignments = std::vector<std::pair<std::string, std::string>>;
  std::vector<std::pair<std::string, std::vector<std::string>>> grid;  // key, values
  std::vector<Assignments> list;

  // "key=v1,v2,v3" (--grid); the key is checked against the schema.
  void addGrid(const std::string& argument);
  // A TOML file with a [grid] table of arrays and [[configs]] tables; errors name the file.
  void loadFile(const std::string& path);
};

// Before any row runs, Configuration::checkApplicable over a sweep's configurations, added one at a
// time (a sweep's points are not held together; finish() after the last): a key the
// sweep sets that has no effect in any configuration it is set in (memory.dram.latency on ideal
// memory, a key rtusim `command` does not use) throws std::invalid_argument naming the key and
// why, since its rows would repeat one run; a key the user gave on the command line or in a file
// is judged over every row as a single run judges it (an error or a warning: reportIneffective),
// so a BIH setting in a sweep over `core` counts the BIH rows; a key without effect in some of the
// configurations is a warning "in N of M configurations" on standard error.
class SettingsEffectCheck {
 public:
  SettingsEffectCheck(unsigned uses, std::string command);
  void add(const Configuration& configuration);
  void finish() const;

 private:
  struct Tally {
    size_t given = 0, ineffective = 0;
    ConfigSource from = ConfigSource::Default;
    std::string reason;
  };
  unsigned uses_;
  std::string command_;
  std::vector<Tally> tallies_;  // one a setting of configSchema()
};

// SettingsEffectCheck over `configurations`.
void checkSettingsHaveEffect(const std::vector<Configuration>& configurations, unsigned uses,
                             const std::string& command);

}  // namespace rtu
