#pragma once
// A core's result whichever kind returned it (CoreKindResult, kinds/registry.h), as the RTU's
// kind-agnostic machinery sees it: the payloads, the host sink, the runs' result columns, the
// statistics, the scene manager's merge and the RTL reference carry it without looking inside.
// What they ask of it, each function below answers with the kind's own static function of the
// same name (rtu/core_kind.h lists them), reached through CoreKindList::visitResult: no virtual
// call, and with one kind no branch either. Each is a template over the kind list so that a test
// can ask them of a list with a kind the registry does not hold; everything else uses CoreKinds.
//
// The outputs that are a kind's own (for SVO the thesis' result buffers and the frame images)
// take a run's results as the kind's own through one function per kind at the end of this file
// (svoResults), which refuses a result of another kind.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "kinds/registry.h"

namespace rtu {

// The kind's name (Kind::kName).
template <class Kinds = CoreKinds>
const char* resultKindName(const typename Kinds::Result& result) {
  return Kinds::visitResult(result, [](auto kind, const auto&) { return decltype(kind)::kName; });
}

// The job's id word, carried back unchanged (the RTL's job_id).
template <class Kinds = CoreKinds>
uint32_t resultIdWord(const typename Kinds::Result& result) {
  return Kinds::visitResult(result, [](auto kind, const auto& own) {
    return decltype(kind)::resultIdWord(own);
  });
}

// Whether the job hit anything.
template <class Kinds = CoreKinds>
bool resultHit(const typename Kinds::Result& result) {
  return Kinds::visitResult(result, [](auto kind, const auto& own) {
    return decltype(kind)::resultHit(own);
  });
}

// The job's cost in cycles: its states' own, blocked cycles excluded (Behaviour::cost()).
template <class Kinds = CoreKinds>
uint32_t resultCost(const typename Kinds::Result& result) {
  return Kinds::visitResult(result, [](auto kind, const auto& own) {
    return decltype(kind)::resultCost(own);
  });
}

// Replaces the cost (the scene manager's merged result: the costs of a ray's jobs summed).
template <class Kinds = CoreKinds>
void setResultCost(typename Kinds::Result& result, uint32_t cost) {
  Kinds::visitResult(result,
                     [cost](auto kind, auto& own) { decltype(kind)::setResultCost(own, cost); });
}

// Whether the result is flagged for reaching below the arithmetic's resolution (the run's
// statistic below_resolution).
template <class Kinds = CoreKinds>
bool resultBelowResolution(const typename Kinds::Result& result) {
  return Kinds::visitResult(result, [](auto kind, const auto& own) {
    return decltype(kind)::resultBelowResolution(own);
  });
}

// Counts the result into its kind's counters among `counters` (a core's statistics, for runs
// that have the results but no core: the recurrence's).
template <class Kinds = CoreKinds>
void countResult(const typename Kinds::Result& result, typename Kinds::Counters& counters) {
  Kinds::visitResult(result, [&counters](auto kind, const auto& own) {
    decltype(kind)::countResult(own, counters);
  });
}

// Whether the result is a hit ahead of the ray's origin: what a scene counts as a hit.
template <class Kinds = CoreKinds>
bool hitAhead(const typename Kinds::Result& result) {
  return Kinds::visitResult(result, [](auto kind, const auto& own) {
    return decltype(kind)::hitAhead(own);
  });
}

// Whether hit `a` is strictly nearer than hit `b`, a result of the same kind (else
// std::bad_variant_access); neither nearer: as near.
template <class Kinds = CoreKinds>
bool nearer(const typename Kinds::Result& a, const typename Kinds::Result& b) {
  return Kinds::visitResult(a, [&b](auto kind, const auto& own) {
    return decltype(kind)::nearer(own, std::get<std::decay_t<decltype(own)>>(b));
  });
}

// How far along the ray the hit lies, in the units of the ray's direction (world units for a
// world-space ray), as its kind's job set-up with its settings in `configs` set the job up.
template <class Kinds = CoreKinds>
double hitDistance(const typename Kinds::Result& result, const typename Kinds::Configs& configs) {
  return Kinds::visitResult(result, [&configs](auto kind, const auto& own) {
    using Kind = decltype(kind);
    return Kind::hitDistance(own, Kinds::template configOf<Kind>(configs));
  });
}

// `result` made a result of `Kind` (its default), returned for the kind to write
// (Kind::writeResult): how a shell of one kind fills a result of any.
template <class Kind, class Kinds = CoreKinds>
typename Kind::Result& emplaceResult(typename Kinds::Result& result) {
  return result.template emplace<typename Kind::Result>();
}
// The same for a new result at the end of `results` (a run's column, by job index).
template <class Kind, class Kinds = CoreKinds>
typename Kind::Result& emplaceBackResult(std::vector<typename Kinds::Result>& results) {
  using Result = typename Kind::Result;
  return *std::get_if<Result>(&results.emplace_back(std::in_place_type<Result>));
}

// A miss of `Kind` carrying `idWord`, with no cost (Kind::miss).
template <class Kind, class Kinds = CoreKinds>
typename Kinds::Result kindMiss(uint32_t idWord) {
  return typename Kinds::Result(std::in_place_type<typename Kind::Result>, Kind::miss(idWord));
}

// The miss of the kind named `core`, chosen once: the scene manager's answer for a ray before any
// of its jobs returned (it never sees the kind). Throws std::invalid_argument for an unknown kind.
using CoreKindMiss = CoreKindResult (*)(uint32_t idWord);
inline CoreKindMiss coreKindMiss(const std::string& core) {
  return withCoreKind(core, [](auto kind) -> CoreKindMiss { return &kindMiss<decltype(kind)>; });
}

// `result` as a result of `Kind`, for the outputs that are that kind's own. Throws
// std::invalid_argument naming both kinds (and `which`, when given) when it is of another kind.
template <class Kind, class Kinds = CoreKinds>
const typename Kind::Result& resultOfKind(const typename Kinds::Result& result,
                                          const std::string& which = "a result") {
  if (const auto* own = std::get_if<typename Kind::Result>(&result)) return *own;
  throw std::invalid_argument(which + " of the '" + resultKindName<Kinds>(result) +
                              "' kind where the '" + Kind::kName + "' kind's are needed");
}

// The same for a run's results, in their order.
template <class Kind, class Kinds = CoreKinds>
std::vector<typename Kind::Result> resultsOfKind(
    const std::vector<typename Kinds::Result>& results) {
  std::vector<typename Kind::Result> own;
  own.reserve(results.size());
  for (const typename Kinds::Result& result : results) {
    const auto* mine = std::get_if<typename Kind::Result>(&result);
    own.push_back(mine ? *mine
                       : resultOfKind<Kind, Kinds>(result, "result " + std::to_string(own.size())));
  }
  return own;
}

// The SVO kind's own outputs take a run's results here: the thesis' result buffers
// (inputs/host_buffers.h, replay), the frame images and scene shading (app/frame_images.h,
// app/scene_shading.cpp); the golden, accuracy and precision commands run the SVO golden model
// itself. Another kind's outputs (a kind's folder cannot name CoreKindResult: the registry lies
// above it, layers.txt) take them as resultsOfKind<Kind>(results), as the triangle kinds' frame
// outputs do (app/frame_outputs.cpp), with nothing added here.
inline const TraversalResult& svoResult(const CoreKindResult& result) {
  return resultOfKind<SvoKind>(result);
}
inline std::vector<TraversalResult> svoResults(const std::vector<CoreKindResult>& results) {
  return resultsOfKind<SvoKind>(results);
}

}  // namespace rtu
