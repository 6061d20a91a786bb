#pragma once
// What declared statistics (base/statistics.h) are written as: JSON objects (`--stats` files,
// sweep and fps rows, a worker's line, read back too), CSV columns, the lines a report has for
// statistics that are reported when not 0, and the table of `rtusim stats --list`. Each of them
// walks a struct's declaration; none names a statistic.

#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "base/statistics.h"

namespace rtu {

// Builds the JSON of the values a declaration writes: '/' in keys nests objects, lists are arrays.
class JsonStatisticWriter final : public StatisticWriter {
 public:
  JsonStatisticWriter();
  void value(const Statistic& statistic, const StatisticValue& value) override;
  void enter(const Statistic& group) override;
  void enterList(const Statistic& list) override;
  void enterPart(size_t index) override;
  void leave() override;
  nlohmann::ordered_json take() { return std::move(root_); }

 private:
  nlohmann::ordered_json& at(const std::string& key);  // below the current object, made on the way
  nlohmann::ordered_json root_;
  std::vector<nlohmann::ordered_json*> open_;
};

// Reads stored values back from such JSON (derived ones are ignored).
class JsonStatisticReader final : public StatisticReader {
 public:
  explicit JsonStatisticReader(const nlohmann::ordered_json& json) : open_{&json} {}
  std::optional<StatisticValue> value(const Statistic& statistic) override;
  bool enter(const Statistic& group) override;
  void leave() override;

 private:
  const nlohmann::ordered_json* find(const std::string& key) const;
  std::vector<const nlohmann::ordered_json*> open_;
};

// Hands each value on with its full key ("cores/3/jobs").
class FlatStatisticWriter final : public StatisticWriter {
 public:
  using Sink = std::function<void(const std::string& key, const Statistic&, const StatisticValue&)>;
  explicit FlatStatisticWriter(Sink sink) : sink_(std::move(sink)) {}
  void value(const Statistic& statistic, const StatisticValue& value) override;
  void enter(const Statistic& group) override { prefixes_.push_back(prefix() + group.key + "/"); }
  void enterList(const Statistic& list) override { enter(list); }
  void enterPart(size_t index) override {
    prefixes_.push_back(prefix() + std::to_string(index) + "/");
  }
  void leave() override { prefixes_.pop_back(); }

 private:
  std::string prefix() const { return prefixes_.empty() ? std::string() : prefixes_.back(); }
  Sink sink_;
  std::vector<std::string> prefixes_;
};

template <class S>
nlohmann::ordered_json statisticsJson(const S& values) {
  JsonStatisticWriter writer;
  S::declaration().write(values, writer);
  return writer.take();
}
template <class S>
void readStatistics(S& values, const nlohmann::ordered_json& json) {
  JsonStatisticReader reader(json);
  S::declaration().read(values, reader);
}

// The values in declaration order with their full keys.
template <class S>
std::vector<std::pair<std::string, StatisticValue>> statisticValues(const S& values) {
  std::vector<std::pair<std::string, StatisticValue>> all;
  FlatStatisticWriter writer([&all](const std::string& key, const Statistic&,
                                    const StatisticValue& value) { all.emplace_back(key, value); });
  S::declaration().write(values, writer);
  return all;
}

// A value as text: integers in full, reals by printf's `realFormat`, intervals as "[low, high]".
std::string statisticText(const StatisticValue& value, const char* realFormat);

// CSV columns of a struct without lists or writtenWhen(): its statistics' keys but those that are
// notAColumn(),
// and one row's fields.
template <class S>
std::vector<std::string> statisticsHeader() {
  std::vector<std::string> keys;
  for (const Statistic& statistic : S::declaration().statistics())
    if (statistic.column) keys.push_back(statistic.key);
  return keys;
}
template <class S>
std::vector<std::string> statisticsFields(const S& values, const char* realFormat) {
  std::vector<std::string> fields;
  FlatStatisticWriter writer(
      [&](const std::string&, const Statistic& statistic, const StatisticValue& value) {
        if (statistic.column) fields.push_back(statisticText(value, realFormat));
      });
  S::declaration().write(values, writer);
  return fields;
}

// "<key, '_' as spaces>: <value> <unit> (<note>)" for each statistic reported when not 0.
void writeReportedLine(std::ostream& out, const Statistic& statistic, const StatisticValue& value);
template <class S>
void writeReportedLines(std::ostream& out, const S& values) {
  FlatStatisticWriter writer(
      [&out](const std::string&, const Statistic& statistic, const StatisticValue& value) {
        if (statistic.reported) writeReportedLine(out, statistic, value);
      });
  S::declaration().write(values, writer);
}

// "sum", "max", "setting", "derived".
const char* combineName(Combine combine);
// `rtusim stats --list`: a heading, then one line a statistic: key, unit, how it combines, doc.
void listStatistics(std::ostream& out, const std::string& heading,
                    const std::vector<Statistic>& statistics);

}  // namespace rtu
