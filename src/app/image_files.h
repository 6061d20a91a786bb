#pragma once
// Memory images as files, whichever kind's (app/kind_image_file.h): the kind a file's header names
// and a call with that kind, chosen once as withCoreKind chooses one.

#include <stdexcept>
#include <string>
#include <vector>

#include "app/kind_image_file.h"
#include "base/choice_list.h"
#include "kind_app_plugins.h"

namespace rtu {

// The name of the kind whose header `words` begin with ("" for none: an SVO image, or no image).
inline std::string imageKindOf(const std::vector<uint32_t>& words) {
  std::string name;
  forEachCoreKind([&](auto kind) {
    using File = KindImageFile<decltype(kind)>;
    if constexpr (File::kByHeader)
      if (name.empty() && File::recognises(words)) name = decltype(kind)::kName;
  });
  return name;
}

// "bvh, bih or kd": the kinds whose images have a header.
inline std::string imageKindNames() {
  std::vector<std::string> names;
  forEachCoreKind([&](auto kind) {
    if constexpr (KindImageFile<decltype(kind)>::kByHeader) names.push_back(decltype(kind)::kName);
  });
  return choiceList(names);
}

// Calls `use(Kind{})` with the kind named `name`, whose image has a header; throws
// std::invalid_argument for another name.
template <class Use>
void withImageKind(const std::string& name, Use&& use) {
  bool found = false;
  forEachCoreKind([&](auto kind) {
    if constexpr (KindImageFile<decltype(kind)>::kByHeader) {
      if (!found && name == decltype(kind)::kName) {
        found = true;
        use(kind);
      }
    }
  });
  if (!found)
    throw std::invalid_argument("no image file of a " + name +
                                " core with a header: " + imageKindNames() + " images have one");
}

}  // namespace rtu
