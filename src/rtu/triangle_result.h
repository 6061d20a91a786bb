#pragma once
// One ray's outcome in a triangle kind (the BVH, BIH and k-d cores): the nearest hit — t, the
// hit triangle's id and barycentrics, in the kind's number format (float32, or seed 004's grid
// integers) and its own convention for u and v — its cost in states, and what the traversal
// counted. Each kind's Result is this with its number and counters; writeTriangleResult is every
// kind's writeResult.

#include <cstdint>

namespace rtu {

template <class Number, class Counts>
struct TriangleResult {
  uint32_t idWord = 0;
  bool hit = false;
  Number t = 0, u = 0, v = 0;  // 0 on a miss
  uint32_t primitive = 0;      // the hit triangle's id; 0 on a miss
  uint32_t cost = 0;
  Counts counts;

  bool operator==(const TriangleResult& o) const {
    return idWord == o.idWord && hit == o.hit && t == o.t && u == o.u && v == o.v &&
           primitive == o.primitive && cost == o.cost && counts == o.counts;
  }
  bool operator!=(const TriangleResult& o) const { return !(*this == o); }
};

// What the RTU's kind-agnostic machinery asks of a result (rtu/core_kind.h), alike for every
// triangle kind: a kind's struct derives from it and adds what depends on its distance (hitAhead,
// nearer, hitDistance) and its record's size.
template <class Result, class Counters>
struct TriangleResultQueries {
  static uint32_t resultIdWord(const Result& result) { return result.idWord; }
  static bool resultHit(const Result& result) { return result.hit; }
  static uint32_t resultCost(const Result& result) { return result.cost; }
  static void setResultCost(Result& result, uint32_t cost) { result.cost = cost; }
  static bool resultBelowResolution(const Result&) { return false; }
  static void countResult(const Result& result, Counters& counters) { counters.add(result.counts); }
  static Result miss(uint32_t idWord) {
    Result result;
    result.idWord = idWord;
    return result;
  }
};

// The result of the job `traversal` ran, under the id word `idWord`.
template <class Number, class Counts, class Traversal>
void writeTriangleResult(uint32_t idWord, const Traversal& traversal,
                         TriangleResult<Number, Counts>& result) {
  result = TriangleResult<Number, Counts>{idWord,           traversal.hit(),   0, 0, 0, 0,
                                          traversal.cost(), traversal.counts()};
  if (!result.hit) return;
  result.t = traversal.t();
  result.u = traversal.u();
  result.v = traversal.v();
  result.primitive = traversal.primitive();
}

}  // namespace rtu
