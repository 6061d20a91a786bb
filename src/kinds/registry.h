#pragma once
// The core kinds rtusim models: one line per kind. Everything that depends on the kind is a
// template over it, instantiated for each kind here, and chosen once at the top of a run by
// withCoreKind (as pbrt-v4's CreateAccelerator chooses an accelerator), so nothing below branches
// on the kind.

#include <cstddef>
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
#include "kinds/bih/bih_kind.h"
#include "kinds/bvh/bvh_kind.h"
#include "kinds/host_record.h"
#include "kinds/kd/kd_kind.h"
#include "kinds/svo/svo_kind.h"
#include "rtu/job_manager_timing.h"

namespace rtu {

template <class... Kinds>
struct CoreKindList {
  // What the job manager hands a core, and what a core returns, whichever kind it is (each kind's
  // own types, distinct from every other kind's).
  using Job = std::variant<typename Kinds::Job...>;
  using Result = std::variant<typename Kinds::Result...>;
  // What the host sends the job manager: any kind's own record or a world-space ray
  // (kinds/host_record.h).
  using HostRecord = HostRecordOf<Kinds...>;
  // The kinds as a type list (Catch2's TEMPLATE_LIST_TEST_CASE runs a test for each).
  using Tuple = std::tuple<Kinds...>;
  // Every kind's own settings, one each whichever kind a run chooses (configOf reaches one).
  using Configs = std::tuple<typename Kinds::Config...>;

  template <class Kind>
  static constexpr bool kHolds = (std::is_same_v<Kind, Kinds> || ...);
  // `Kind`'s settings in `configs` (a Configs, const or not). A kind outside the list (a test's)
  // has its defaults, read-only.
  template <class Kind, class ConfigTuple>
  static auto& configOf(ConfigTuple& configs) {
    if constexpr (kHolds<Kind>) {
      return std::get<indexOf<Kind>()>(configs);
    } else {
      static_assert(std::is_const_v<ConfigTuple>, "only a listed kind's settings can be set");
      static const typename Kind::Config defaults{};
      return defaults;
    }
  }
  // Throws std::invalid_argument naming the setting for any kind's settings its core cannot have
  // (Config::validate), whichever kind a run chooses, as memory settings are checked with ideal
  // memory.
  static void validateConfigs(const Configs& configs) {
    (configOf<Kinds>(configs).validate(), ...);
  }
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
  // For a run's statistics V (StatisticGroup<V>::extend): the counters of the kind its cores
  // are of and no other's, each kind's Counters computed by `counters(values)` (the cores' counters
  // summed) and written only when `kind(values)` is its name.
  template <class V, class KindOf, class CountersOf>
  static auto runCounters(KindOf kind, CountersOf counters) {
    return [kind, counters](StatisticGroup<V>& group) {
      (group
           .template computed<typename Kinds::Counters>(
               Statistic("", "", ""),
               [counters](const V& values) -> typename Kinds::Counters { return counters(values); })
           .writtenWhen([kind](const V& values) { return kind(values) == Kinds::kName; }),
       ...);
    };
  }
  static std::vector<std::string> names() { return {Kinds::kName...}; }
  // "name: description" of each kind, separated by "; " (the schema's text for `core`).
  static std::string described() {
    std::string text;
    ((text += (text.empty() ? "" : "; ") + std::string(Kinds::kName) + ": " + Kinds::kDescription),
     ...);
    return text;
  }

  // Calls `visit(Kind{}, own)` with the kind whose result `result` holds and that result (const
  // as `result` is): how kind-agnostic code reaches a result's kind (kinds/core_result.h). One
  // test of the variant's index per kind but the last, none with one kind; no virtual call. (A
  // result is never valueless: results are plain records, made without throwing.)
  template <size_t I = 0, class Variant, class Visit>
  static decltype(auto) visitResult(Variant& result, Visit&& visit) {
    using Kind = std::tuple_element_t<I, Tuple>;
    if constexpr (I + 1 < sizeof...(Kinds)) {
      if (result.index() != I) return visitResult<I + 1>(result, std::forward<Visit>(visit));
    }
    auto* own = std::get_if<I>(&result);
    if (own == nullptr) __builtin_unreachable();  // the last kind left: the result is its
    return visit(Kind{}, *own);
  }

 private:
  template <class Kind>
  static constexpr size_t indexOf() {
    size_t index = 0;
    (void)((std::is_same_v<Kind, Kinds> ? true : (++index, false)) || ...);
    return index;
  }
};

using CoreKinds =
    CoreKindList<SvoKind, BvhKind<>, BihKind<>, KdKind>;  // a new kind: one more name here

using HostRecord = CoreKinds::HostRecord;
using CoreKindConfigs = CoreKinds::Configs;
using CoreKindJob = CoreKinds::Job;
using CoreKindResult = CoreKinds::Result;
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

// Calls `visit(Kind{})` for every kind, in the registry's order.
template <class Visit>
void forEachCoreKind(Visit&& visit) {
  std::apply([&visit](auto... kinds) { (visit(kinds), ...); }, CoreKinds::Tuple{});
}

// Throws std::invalid_argument naming the record and the kind when the kind named `core` takes no
// set-up overload for one of `records`; the runs call it before they start.
inline void checkCoreTakes(const std::string& core, const std::vector<HostRecord>& records) {
  withCoreKind(core, [&records](auto kind) { checkTakesRecords<decltype(kind)>(records); });
}

// The job manager's set-up of host records for the kind named `core` (its Kind::Setup, from its
// settings in `configs`), behind one call per job: the job manager stays kind-agnostic, and
// nothing per cycle goes through it. A record the kind takes no overload for throws
// std::invalid_argument (setUpHostRecord).
using CoreJobSetup = std::function<CoreKindJobSetUp(const HostRecord&)>;

inline CoreJobSetup makeCoreJobSetup(const std::string& core, WordMemory memory,
                                     const JobManagerTiming& timing,
                                     const CoreKindConfigs& configs) {
  return withCoreKind(core, [&](auto kind) -> CoreJobSetup {
    using Kind = decltype(kind);
    return [setup = typename Kind::Setup(memory, timing, CoreKinds::configOf<Kind>(configs))](
               const HostRecord& record) mutable {
      auto set = setUpHostRecord<Kind>(setup, record);
      return CoreKindJobSetUp{CoreKindJob{set.job}, set.idWord, set.latency, set.headerFetch};
    };
  });
}

}  // namespace rtu
