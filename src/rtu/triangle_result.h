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
