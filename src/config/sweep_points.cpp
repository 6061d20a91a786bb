#include "config/sweep_points.h"

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>

namespace rtu {
namespace {

// The configuration `base` with `assignments` set, as its JSON text: how two values or entries
// are compared.
std::string configurationText(const Configuration& base, const SweepSpec::Assignments& assignments,
                              const std::vector<std::string>& ignored = {}) {
  Configuration configuration = base;
  for (const auto& [key, value] : assignments) configuration.set(key, value, ConfigSource::Sweep);
  nlohmann::ordered_json json = configuration.toJson();
  for (const std::string& key : ignored) json.erase(key);
  return json.dump();
}

}  // namespace

SweepPoints::SweepPoints(const SweepSpec& spec, const Configuration& base) : base_(base) {
  std::vector<std::string> gridded;
  for (size_t k = 0; k < spec.grid.size(); ++k) {
    const auto& [key, values] = spec.grid[k];
    const bool later = std::any_of(spec.grid.begin() + static_cast<long>(k) + 1, spec.grid.end(),
                                   [&key = key](const auto& axis) { return axis.first == key; });
    std::vector<std::string> distinct;
    std::set<std::string> seen;
    for (const std::string& value : values)
      if (seen.insert(configurationText(base, {{key, value}})).second) distinct.push_back(value);
    if (later) continue;  // overridden by the later grid of the same key
    if (!distinct.empty() && gridSize_ > std::numeric_limits<size_t>::max() / distinct.size())
      throw std::invalid_argument("the sweep grid has more than 2^64 points: sweep fewer values");
    gridSize_ *= distinct.size();
    axes_.emplace_back(key, distinct);
    gridded.push_back(key);
  }
  std::set<std::string> seen;
  for (const SweepSpec::Assignments& entry : spec.list)
    if (seen.insert(configurationText(base, entry, gridded)).second) entries_.push_back(entry);
  if (entries_.empty()) entries_.emplace_back();
  if (gridSize_ > 0 && entries_.size() > std::numeric_limits<size_t>::max() / gridSize_)
    throw std::invalid_argument("the sweep has more than 2^64 points: sweep fewer values");
}

SweepSpec::Assignments SweepPoints::assignments(size_t i) const {
  SweepSpec::Assignments point = entries_.at(i / gridSize_);
  size_t rest = i % gridSize_;
  const size_t first = point.size();
  for (size_t k = axes_.size(); k-- > 0;) {
    const std::vector<std::string>& values = axes_[k].second;
    point.emplace(point.begin() + static_cast<long>(first), axes_[k].first,
                  values[rest % values.size()]);
    rest /= values.size();
  }
  return point;
}

Configuration SweepPoints::at(size_t i) const {
  Configuration configuration = base_;
  for (const auto& [key, value] : assignments(i))
    configuration.set(key, value, ConfigSource::Sweep);
  return configuration;
}

std::string SweepPoints::describe(size_t i) const {
  std::string text;
  for (const auto& [key, value] : assignments(i))
    text += (text.empty() ? "" : " ") + key + "=" + value;
  return text;
}

nlohmann::ordered_json SweepPoints::toJson() const {
  nlohmann::ordered_json json = {{"base", base_.toJson()}, {"grid", axes_}, {"list", entries_}};
  return json;
}

SweepPoints SweepPoints::fromJson(const nlohmann::ordered_json& json) {
  SweepPoints points;
  points.base_.loadText(json.at("base").dump(), "json", "the sweep plan's base",
                        ConfigSource::File);
  json.at("grid").get_to(points.axes_);
  json.at("list").get_to(points.entries_);
  for (const auto& axis : points.axes_) points.gridSize_ *= axis.second.size();
  return points;
}

}  // namespace rtu
