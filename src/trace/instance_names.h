#pragma once
// Numbered instances in trace scopes (rtu.core_3, rtu.memory.l1_3) zero-padded to the width of the
// largest number of their kind (core_03 when there are 10 to 100 cores), so viewers that sort by
// name list them in order. Scope filters match either spelling: rtu.core_3 and rtu.core_03 are
// the same scope.

#include <map>
#include <string>

namespace rtu {

// The scope with every instance number written without leading zeros.
std::string unpaddedScope(const std::string& scope);

class InstanceWidths {
 public:
  // Notes the instance numbers of a scope.
  void add(const std::string& scope);
  // The scope with each instance number padded to the width of the largest of its kind.
  std::string padded(const std::string& scope) const;

 private:
  std::map<std::string, size_t> digits_;  // "core_" -> digits of the largest number
};

}  // namespace rtu
