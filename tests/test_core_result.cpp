// The kind-agnostic view of a core's result (kinds/core_result.h) over a kind list the registry
// does not hold: the SVO kind and the toy kind of toy_kind.h. Each helper must reach the kind of
// the result it is given, whichever alternative of the list that is, and a kind's own outputs
// must refuse a result of another kind, naming both.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "kinds/core_result.h"
#include "rtu/golden_shell.h"
#include "toy_kind.h"

namespace rtu {
namespace {

using ToyKinds = CoreKindList<SvoKind, ToyKind>;
using AnyResult = ToyKinds::Result;

// A toy result of `sum` and `cost`, as a result of the list.
AnyResult toy(uint32_t idWord, uint32_t sum, uint32_t cost) {
  return AnyResult(std::in_place_type<ToyResult>, ToyResult{idWord, sum, cost});
}

}  // namespace

TEST_CASE("Kind-agnostic results: a toy kind's result answers through its own functions",
          "[kinds]") {
  // The toy shell writes a job's result into a result of the list (as the LT top and the analytic
  // run write theirs): words 0, 1, 5, 4 and 2, 3 of the walk from base 0 (toy_kind.h).
  const std::vector<uint32_t> words = {10, 20, 30, 40, 50, 60, 70, 80};
  GoldenShell<ToyKind> shell{WordMemory(words), ToyKind::Config{}};
  AnyResult result;  // the SVO kind's, the list's first
  REQUIRE(std::holds_alternative<TraversalResult>(result));
  shell.run(9, 0, emplaceResult<ToyKind, ToyKinds>(result));
  REQUIRE(std::holds_alternative<ToyResult>(result));
  CHECK(std::get<ToyResult>(result) == ToyResult{9, 10 + 20 + 60 + 50 + 30 + 40, 9});

  CHECK(std::string(resultKindName<ToyKinds>(result)) == "toy");
  CHECK(resultIdWord<ToyKinds>(result) == 9);
  CHECK(resultHit<ToyKinds>(result));
  CHECK(resultCost<ToyKinds>(result) == 9);
  setResultCost<ToyKinds>(result, 25);
  CHECK(resultCost<ToyKinds>(result) == 25);
  CHECK(std::get<ToyResult>(result).sum == 210);  // the rest untouched
  CHECK_FALSE(resultBelowResolution<ToyKinds>(result));
  CHECK(resultBelowResolution<ToyKinds>(toy(1, 1, 1)));

  // Counted into the toy's counters, the SVO kind's untouched.
  ToyKinds::Counters counters;
  countResult<ToyKinds>(toy(1, 7, 1), counters);
  countResult<ToyKinds>(toy(2, 8, 1), counters);
  countResult<ToyKinds>(toy(3, 9, 1), counters);
  CHECK(counters.oddSums == 2);
  CHECK(counters.stackOverflows == 0);
  CHECK(counters.tOverflows == 0);
}

TEST_CASE("Kind-agnostic results: the scene manager's questions of a toy kind", "[kinds]") {
  const AnyResult miss = kindMiss<ToyKind, ToyKinds>(42);
  REQUIRE(std::holds_alternative<ToyResult>(miss));
  CHECK(resultIdWord<ToyKinds>(miss) == 42);
  CHECK_FALSE(resultHit<ToyKinds>(miss));
  CHECK(resultCost<ToyKinds>(miss) == 0);
  CHECK_FALSE(hitAhead<ToyKinds>(miss));

  const AnyResult near = toy(1, 3, 5), far = toy(2, 8, 5), alsoNear = toy(3, 3, 7);
  CHECK(hitAhead<ToyKinds>(near));
  CHECK(nearer<ToyKinds>(near, far));
  CHECK_FALSE(nearer<ToyKinds>(far, near));
  CHECK_FALSE(nearer<ToyKinds>(near, alsoNear));  // as near: neither is nearer
  CHECK_FALSE(nearer<ToyKinds>(alsoNear, near));
  CHECK(hitDistance<ToyKinds>(far, ToyKinds::Configs{}) == 8.0);

  // Two results of different kinds have no order.
  const AnyResult svo = kindMiss<SvoKind, ToyKinds>(1);
  CHECK_THROWS_AS(nearer<ToyKinds>(near, svo), std::bad_variant_access);
}

TEST_CASE("Kind-agnostic results: the SVO kind's answers through the same list", "[kinds]") {
  TraversalResult hit;
  hit.idWord = 5 | 3u << 28;
  hit.hit = true;
  hit.tHit = -(int64_t{3} << 16);  // behind the origin (Q16.16): no hit for a scene
  hit.cost = 17;
  hit.stackOverflow = true;
  hit.belowResolution = true;
  AnyResult result = hit;
  CHECK(std::string(resultKindName<ToyKinds>(result)) == "svo");
  CHECK(resultIdWord<ToyKinds>(result) == hit.idWord);
  CHECK(resultHit<ToyKinds>(result));
  CHECK_FALSE(hitAhead<ToyKinds>(result));
  CHECK(resultCost<ToyKinds>(result) == 17);
  CHECK(resultBelowResolution<ToyKinds>(result));
  CHECK(hitDistance<ToyKinds>(result, ToyKinds::Configs{}) == -3.0);
  ToyKinds::Counters counters;
  countResult<ToyKinds>(result, counters);
  CHECK(counters.stackOverflows == 1);
  CHECK(counters.tOverflows == 0);
  CHECK(counters.oddSums == 0);
}

TEST_CASE("Kind-agnostic results: a kind's own outputs refuse another kind's results", "[kinds]") {
  const std::vector<AnyResult> results = {toy(0, 1, 1), toy(1, 2, 2)};
  const std::vector<ToyResult> own = resultsOfKind<ToyKind, ToyKinds>(results);
  REQUIRE(own.size() == 2);
  CHECK(own[1] == ToyResult{1, 2, 2});

  const std::vector<AnyResult> mixed = {toy(0, 1, 1), kindMiss<SvoKind, ToyKinds>(1)};
  CHECK_THROWS_WITH((resultsOfKind<ToyKind, ToyKinds>(mixed)),
                    "result 1 of the 'svo' kind where the 'toy' kind's are needed");
  CHECK_THROWS_AS((resultOfKind<SvoKind, ToyKinds>(results[0])), std::invalid_argument);

  // The registry's SVO outputs take SVO results as they are.
  TraversalResult svo;
  svo.idWord = 3;
  svo.cost = 4;
  const std::vector<TraversalResult> back = svoResults({CoreKindResult(svo)});
  REQUIRE(back.size() == 1);
  CHECK(back[0] == svo);
}

}  // namespace rtu
