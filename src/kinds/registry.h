#pragma once
// The core kinds rtusim models: one line per kind. Everything that depends on the kind is a
// template over it, instantiated for each kind here, and chosen once at the top of a run by
// withCoreKind (as pbrt-v4's CreateAccelerator chooses an accelerator), so nothing below branches
// on the kind.

#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "kinds/svo/svo_kind.h"

namespace rtu {

template <class... Kinds>
struct CoreKindList {
  // What the job manager hands a core, whichever kind it is.
  using Job = std::variant<typename Kinds::Job...>;
  // The kinds as a type list (Catch2's TEMPLATE_LIST_TEST_CASE runs a test for each).
  using Tuple = std::tuple<Kinds...>;
  static std::vector<std::string> names() { return {Kinds::kName...}; }
};

using CoreKinds = CoreKindList<SvoKind>;  // a new kind: one more name here

using CoreKindJob = CoreKinds::Job;

// Calls `use(Kind{})` with the kind named `name`; throws std::invalid_argument naming the kinds
// for an unknown one.
template <class Use, class... Kinds>
auto withCoreKindOf(CoreKindList<Kinds...>, const std::string& name, Use&& use) {
  using Result = decltype(use(std::declval<std::tuple_element_t<0, std::tuple<Kinds...>>>()));
  if constexpr (std::is_void_v<Result>) {
    const bool found = ((name == Kinds::kName ? (use(Kinds{}), true) : false) || ...);
    if (!found) throw std::invalid_argument("unknown core kind '" + name + "'");
  } else {
    std::optional<Result> result;
    ((name == Kinds::kName ? (result.emplace(use(Kinds{})), true) : false) || ...);
    if (!result) throw std::invalid_argument("unknown core kind '" + name + "'");
    return *std::move(result);
  }
}

template <class Use>
auto withCoreKind(const std::string& name, Use&& use) {
  return withCoreKindOf(CoreKinds{}, name, std::forward<Use>(use));
}

}  // namespace rtu
