#include "explore/architecture_resources.h"

#include "explore/exploration_run.h"
#include "raypipe/raypipe_resources.h"
#include "sim/rtu_resources.h"

namespace rtu {

using Json = nlohmann::ordered_json;

ResourceEstimate architectureResources(const RunConfig& settings, uint64_t imageWords) {
  if (settings.architecture == Architecture::Raypipe) return raypipeResources(settings.raypipe);
  return rtuResources(settings.rtu, imageWords);
}

Json resourcesJson(const ResourceEstimate& estimate) {
  Json memories = Json::array(), units = Json::array();
  for (const MemoryArray& array : estimate.memories)
    memories.push_back({{"name", array.name},
                        {"depth", array.depth},
                        {"width", array.width},
                        {"count", array.count},
                        {"bits", array.bits()},
                        {"bram18k", array.count * blockRamsOf(array.depth, array.width)}});
  for (const ArithmeticUnits& unit : estimate.units)
    units.push_back({{"where", unit.where},
                     {"kind", toString(unit.kind)},
                     {"number", toString(unit.number)},
                     {"width", unit.width},
                     {"other_width", unit.otherWidth > 0 ? unit.otherWidth : unit.width},
                     {"count", unit.count},
                     {"dsp48e", unit.count * dsp48eOf(unit)}});
  return {{"memory_bits", estimate.memoryBits()},
          {"bram_bits", estimate.blockRamBits()},
          {"bram18k", estimate.blockRams()},
          {"dsp48e", estimate.dsp48e()},
          {"multipliers", estimate.unitCount(ArithmeticKind::Multiplier)},
          {"adders", estimate.unitCount(ArithmeticKind::Adder)},
          {"dividers", estimate.unitCount(ArithmeticKind::Divider)},
          {"comparators", estimate.unitCount(ArithmeticKind::Comparator)},
          {"luts", estimate.luts()},
          {"memories", memories},
          {"units", units}};
}

const std::vector<std::string>& resourceColumns() {
  static const std::vector<std::string> columns = {"memory_bits", "bram_bits",   "bram18k",
                                                   "dsp48e",      "multipliers", "adders",
                                                   "dividers",    "comparators", "luts"};
  return columns;
}

std::vector<std::string> resourceValues(const Json& row) {
  std::vector<std::string> values;
  const bool has = row.contains("resources");
  for (const std::string& column : resourceColumns())
    values.push_back(has ? csvValue(row["resources"][column]) : "");
  return values;
}

Json perResource(const Json& fps, const Json& amount) {
  if (!fps.is_number() || !amount.is_number() || amount.get<double>() <= 0) return Json();
  return fps.get<double>() / amount.get<double>();
}

}  // namespace rtu
