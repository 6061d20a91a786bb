#pragma once
// The core kinds rtusim models: one line per kind. Everything that depends on the kind is a
// template over it, instantiated for each kind here, and chosen once at the top of a run by
// withCoreKind (as pbrt-v4's CreateAccelerator chooses an accelerator), so nothing below branches
// on the kind.

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "base/statistics.h"
#include "kinds/svo/svo_kind.h"

namespace rtu {

template <class... Kinds>
struct CoreKindList {
  // What the job manager hands a core, whichever kind it is.
  using Job = std::variant<typename Kinds::Job...>;
  // The kinds as a type list (Catch2's TEMPLATE_LIST_TEST_CASE runs a test for each).
  using Tuple = std::tuple<Kinds...>;
  // Every kind's own counters, held by a core's statistics (kinds/core_statistics.h).
  struct Counters : Kinds::Counters... {
    static const StatisticGroup<Counters>& declaration() {
      static const StatisticGroup<Counters> group = [] {
        StatisticGroup<Counters> kinds("the core kinds' counters");
        (kinds.template base<typename Kinds::Counters>(), ...);
        return kinds;
      }();
      return group;
    }
  };
  static std::vector<std::string> names() { return {Kinds::kName...}; }
};

using CoreKinds = CoreKindList<SvoKind>;  // a new kind: one more name here

using CoreKindJob = CoreKinds::Job;
using CoreKindJobSetUp = JobSetUp<CoreKindJob>;

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

// The job manager's set-up of host records for the kind named `core` (its Kind::Setup), behind
// one call per job: the job manager stays kind-agnostic, and nothing per cycle goes through it.
using CoreJobSetup = std::function<CoreKindJobSetUp(const HostRecord&)>;

inline CoreJobSetup makeCoreJobSetup(const std::string& core, WordMemory memory,
                                     const JobManagerConfig& config) {
  return withCoreKind(core, [&](auto kind) -> CoreJobSetup {
    return
        [setup = typename decltype(kind)::Setup(memory, config)](const HostRecord& record) mutable {
          auto set = setup.setUp(record);
          return CoreKindJobSetUp{CoreKindJob{set.job}, set.idWord, set.latency, set.headerFetch};
        };
  });
}

}  // namespace rtu
