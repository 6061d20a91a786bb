#include "trace/instance_names.h"

#include <algorithm>
#include <functional>
#include <vector>

namespace rtu {
namespace {

// A scope component "core_03": its kind "core_" and number "03"; number empty for other names.
std::pair<std::string, std::string> splitInstance(const std::string& component) {
  const size_t underscore = component.rfind('_');
  if (underscore == std::string::npos || underscore + 1 == component.size()) return {component, ""};
  const std::string number = component.substr(underscore + 1);
  if (!std::all_of(number.begin(), number.end(), ::isdigit)) return {component, ""};
  return {component.substr(0, underscore + 1), number};
}

std::string withoutZeros(const std::string& number) {
  const size_t first = number.find_first_not_of('0');
  return first == std::string::npos ? "0" : number.substr(first);
}

// Applies `rename(kind, number)` to every numbered component of the dot-separated scope.
std::string mapInstances(
    const std::string& scope,
    const std::function<std::string(const std::string&, const std::string&)>& rename) {
  std::string result;
  size_t start = 0;
  while (true) {
    const size_t dot = scope.find('.', start);
    const std::string component = scope.substr(start, dot == std::string::npos ? dot : dot - start);
    const auto [kind, number] = splitInstance(component);
    result += number.empty() ? component : kind + rename(kind, withoutZeros(number));
    if (dot == std::string::npos) return result;
    result += '.';
    start = dot + 1;
  }
}

}  // namespace

std::string unpaddedScope(const std::string& scope) {
  return mapInstances(scope, [](const std::string&, const std::string& number) { return number; });
}

void InstanceWidths::add(const std::string& scope) {
  mapInstances(scope, [this](const std::string& kind, const std::string& number) {
    digits_[kind] = std::max(digits_[kind], number.size());
    return number;
  });
}

std::string InstanceWidths::padded(const std::string& scope) const {
  return mapInstances(scope, [this](const std::string& kind, const std::string& number) {
    const auto width = digits_.find(kind);
    const size_t digits = width == digits_.end() ? number.size() : width->second;
    return std::string(digits > number.size() ? digits - number.size() : 0, '0') + number;
  });
}

}  // namespace rtu
