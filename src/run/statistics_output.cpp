#include "run/statistics_output.h"

#include <cstdio>
#include <iomanip>
#include <ostream>

namespace rtu {
namespace {

using Json = nlohmann::ordered_json;

std::vector<std::string> pathOf(const std::string& key) {
  std::vector<std::string> parts;
  size_t from = 0;
  for (size_t slash = key.find('/'); slash != std::string::npos; slash = key.find('/', from)) {
    parts.push_back(key.substr(from, slash - from));
    from = slash + 1;
  }
  parts.push_back(key.substr(from));
  return parts;
}

Json jsonOf(const Statistic& statistic, const StatisticValue& value) {
  return std::visit(
      [&statistic](const auto& v) -> Json {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, Histogram>) {
          if (statistic.form == HistogramForm::Object) {
            Json keyed = Json::object();
            for (const auto& [at, times] : v) keyed[std::to_string(at)] = times;
            return keyed;
          }
          std::vector<uint64_t> dense(v.empty() ? 0 : v.rbegin()->first + 1);
          for (const auto& [at, times] : v) dense[at] = times;
          return dense;
        } else {
          return v;
        }
      },
      value);
}

}  // namespace

JsonStatisticWriter::JsonStatisticWriter() : root_(Json::object()), open_{&root_} {}

Json& JsonStatisticWriter::at(const std::string& key) {
  Json* place = open_.back();
  for (const std::string& part : pathOf(key)) place = &(*place)[part];
  return *place;
}

void JsonStatisticWriter::value(const Statistic& statistic, const StatisticValue& value) {
  at(statistic.key) = jsonOf(statistic, value);
}

void JsonStatisticWriter::enter(const Statistic& group) {
  Json& object = at(group.key);
  if (object.is_null()) object = Json::object();
  open_.push_back(&object);
}

void JsonStatisticWriter::enterList(const Statistic& list) {
  Json& array = at(list.key);
  array = Json::array();
  open_.push_back(&array);
}

void JsonStatisticWriter::enterPart(size_t) {
  open_.back()->push_back(Json::object());
  open_.push_back(&open_.back()->back());
}

void JsonStatisticWriter::leave() { open_.pop_back(); }

const Json* JsonStatisticReader::find(const std::string& key) const {
  const Json* place = open_.back();
  for (const std::string& part : pathOf(key)) {
    if (!place->is_object() || !place->contains(part)) return nullptr;
    place = &(*place)[part];
  }
  return place;
}

std::optional<StatisticValue> JsonStatisticReader::value(const Statistic& statistic) {
  const Json* value = find(statistic.key);
  if (!value) return std::nullopt;
  if (value->is_number_unsigned()) return value->get<uint64_t>();
  if (value->is_number_integer()) return value->get<int64_t>();
  if (value->is_number_float()) return value->get<double>();
  if (value->is_string()) return value->get<std::string>();
  Histogram histogram;
  if (value->is_object())
    for (const auto& [at, times] : value->items())
      histogram[std::stoull(at)] = times.get<uint64_t>();
  else if (value->is_array())
    for (size_t at = 0; at < value->size(); ++at)
      if (const uint64_t times = (*value)[at].get<uint64_t>()) histogram[at] = times;
  return histogram;
}

bool JsonStatisticReader::enter(const Statistic& group) {
  const Json* object = find(group.key);
  if (!object || !object->is_object()) return false;
  open_.push_back(object);
  return true;
}

void JsonStatisticReader::leave() { open_.pop_back(); }

void FlatStatisticWriter::value(const Statistic& statistic, const StatisticValue& value) {
  sink_(prefix() + statistic.key, statistic, value);
}

std::string statisticText(const StatisticValue& value, const char* realFormat) {
  return std::visit(
      [realFormat](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        const auto real = [realFormat](double x) {
          char text[64];
          std::snprintf(text, sizeof text, realFormat, x);
          return std::string(text);
        };
        if constexpr (std::is_same_v<T, double>) {
          return real(v);
        } else if constexpr (std::is_same_v<T, std::string>) {
          return v;
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          std::string text = "[";
          for (size_t i = 0; i < v.size(); ++i) text += (i ? ", " : "") + real(v[i]);
          return text + "]";
        } else if constexpr (std::is_same_v<T, Histogram>) {
          std::string text;
          for (const auto& [at, times] : v)
            text += (text.empty() ? "" : " ") + std::to_string(at) + ":" + std::to_string(times);
          return text;
        } else {
          return std::to_string(v);
        }
      },
      value);
}

void writeReportedLine(std::ostream& out, const Statistic& statistic, const StatisticValue& value) {
  const bool zero = std::visit(
      [](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_arithmetic_v<T>)
          return v == 0;
        else
          return v.empty();
      },
      value);
  if (zero) return;
  std::string label = statistic.key.substr(statistic.key.rfind('/') + 1);
  for (char& c : label) c = c == '_' ? ' ' : c;
  out << label << ": " << statisticText(value, "%g") << (statistic.unit.empty() ? "" : " ")
      << statistic.unit << (statistic.note.empty() ? "" : " (" + statistic.note + ")") << "\n";
}

const char* combineName(Combine combine) {
  switch (combine) {
    case Combine::Sum: return "sum";
    case Combine::Max: return "max";
    case Combine::Setting: return "setting";
    case Combine::Derived: return "derived";
  }
  return "";
}

void listStatistics(std::ostream& out, const std::string& heading,
                    const std::vector<Statistic>& statistics) {
  out << heading << "\n"
      << std::left << std::setw(44) << "key" << std::setw(14) << "unit" << std::setw(9) << "combine"
      << "doc\n";
  for (const Statistic& s : statistics)
    out << std::setw(44) << s.key << std::setw(14) << (s.unit.empty() ? "-" : s.unit)
        << std::setw(9) << combineName(s.combine) << s.doc << "\n";
}

}  // namespace rtu
