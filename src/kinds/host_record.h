#pragma once
// What the host sends the job manager, whichever kinds of core the registry holds: a world-space
// ray record (rtu/ray_record.h), which every kind's set-up takes, or a kind's own record
// (Kind::Record, when it declares one: the SVO kind's t-value record). A kind's Setup offers a
// setUp overload for each record it takes; setUpHostRecord picks it, and refuses a record the
// kind has none for (checkTakesRecords refuses it before a run). Every record type names itself
// (`kName`) for that refusal.

#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

#include "rtu/core_kind.h"
#include "rtu/ray_record.h"

namespace rtu {

// The kind's own record as a type list: empty for a kind that takes rays only.
template <class Kind, class = void>
struct OwnRecords {
  using List = std::tuple<>;
};
template <class Kind>
struct OwnRecords<Kind, std::void_t<typename Kind::Record>> {
  using List = std::tuple<typename Kind::Record>;
};

// A variant of the types in the type list Rest, each once, in the order of its first appearance
// after the Chosen ones.
template <class Chosen, class Rest>
struct DistinctVariant;
template <class... Chosen>
struct DistinctVariant<std::variant<Chosen...>, std::tuple<>> {
  using Type = std::variant<Chosen...>;
};
template <class... Chosen, class Next, class... Rest>
struct DistinctVariant<std::variant<Chosen...>, std::tuple<Next, Rest...>>
    : DistinctVariant<std::conditional_t<(std::is_same_v<Next, Chosen> || ...),
                                         std::variant<Chosen...>, std::variant<Chosen..., Next>>,
                      std::tuple<Rest...>> {};

// The host records of the kinds `Kinds`: their own records (each once, in the kinds' order), then
// the ray record. The order is the variant's index, which the host buffers do not store.
template <class... Kinds>
using HostRecordOf = typename DistinctVariant<
    std::variant<>, decltype(std::tuple_cat(std::declval<typename OwnRecords<Kinds>::List>()...,
                                            std::declval<std::tuple<RayRecord>>()))>::Type;

// Whether a kind's set-up takes a record of type `Record`: has a setUp overload for it.
template <class Kind, class Record, class = void>
constexpr bool kTakesRecord = false;
template <class Kind, class Record>
constexpr bool kTakesRecord<Kind, Record,
                            std::void_t<decltype(std::declval<typename Kind::Setup&>().setUp(
                                std::declval<const Record&>()))>> = true;

// The refusal of a record a kind's set-up does not take.
template <class Kind, class Record>
std::invalid_argument refusedRecord() {
  return std::invalid_argument(std::string("the ") + Kind::kName + " core takes no " +
                               Record::kName + "s");
}

// `record` (a HostRecordOf) set up by the kind's `setup`, through the overload for its type; throws
// std::invalid_argument naming the record and the kind when the kind has none.
template <class Kind, class HostRecord>
JobSetUp<typename Kind::Job> setUpHostRecord(typename Kind::Setup& setup,
                                             const HostRecord& record) {
  return std::visit(
      [&setup](const auto& own) -> JobSetUp<typename Kind::Job> {
        using Record = std::decay_t<decltype(own)>;
        if constexpr (kTakesRecord<Kind, Record>)
          return setup.setUp(own);
        else
          throw refusedRecord<Kind, Record>();
      },
      record);
}

// Throws refusedRecord's std::invalid_argument for the first of `records` (HostRecordOf values)
// the kind takes no overload for: a run checks its records before it starts. No test at all for
// a kind that takes every record.
template <class Kind, class HostRecord>
void checkTakesRecords(const std::vector<HostRecord>& records) {
  for (const HostRecord& record : records)
    std::visit(
        [](const auto& own) {
          using Record = std::decay_t<decltype(own)>;
          if constexpr (!kTakesRecord<Kind, Record>) throw refusedRecord<Kind, Record>();
        },
        record);
}

}  // namespace rtu
