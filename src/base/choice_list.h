#pragma once
// A list of choices as a message names them: "bvh, bih or kdtree".

#include <string>
#include <vector>

namespace rtu {

inline std::string choiceList(const std::vector<std::string>& names) {
  std::string text;
  for (size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return text;
}

}  // namespace rtu
