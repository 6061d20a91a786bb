#pragma once
// The cycles of seed 004's BIH core (issue 28; docs/triangles.md, "The BIH core"). The six states
// of Table 3.1 (AABB, NODE, INNER, PUSH, POP, LEAF) take one cycle each, as Listing A.3's state
// machine steps once a clock; so do the record fetches TRI0-2, an access each. The ray/triangle
// unit is pipelined, one per core: S4 §3.3 p.41 L537 gives it 41 cycles of delay at n = 29,
// m = 32 and "one ray/triangle intersection per cycle". TEST issues a test to it and takes the
// unit's initiation interval `triangleInterval`. The traversal does not wait for results: the
// BIH "outputs triangle numbers, as long as it is in state leaf" (§3.4 p.43 L566) and has no
// early-out because "the information sent back from the intersection result would reach the BIH
// much too late" (L568). So only the ray's last state waits, until the result of the last test
// issued is out: a test issued at cycle c (the start of its TEST) answers at c + `triangleLatency`,
// and the last state ends no earlier. A leaf of k triangles so takes k x (4 + interval) cycles
// (LEAF, TRI0-2, TEST each), and a ray whose last test issued at c ends at
// max(its last state's start + 1, c + latency). (The BVH core waits the latency after each leaf
// instead: its POP skips by the nearest hit, bvh_timing.h.)

#include <cstdint>

namespace rtu {

// The seed's unit: 41 cycles at n = 29, m = 32 (S4 §3.3 L537), one test a cycle.
constexpr uint32_t kBihSeedTriangleLatency = 41;

struct BihCycles {
  uint32_t triangleLatency = kBihSeedTriangleLatency;
  uint32_t triangleInterval = 1;
};

}  // namespace rtu
