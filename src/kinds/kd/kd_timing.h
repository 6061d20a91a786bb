#pragma once
// The cycles of the k-d core's states (issue 28; docs/triangles.md, "The k-d core"), the shared
// triangle cores' unit settings (core.box.latency, core.triangle.latency, core.triangle.interval):
//   SINT, TRAV    `boxLatency` each: SINT's slab test of the scene box and TRAV's plane test
//                 (one subtraction and one division, S1 §2.6.7) take the node unit's cycles
//   NODE, LIST, UTTM0-2, POP   one cycle each: a memory state issues one 4-word access, POP
//                 reads the core's own short stack (or its restart record)
//   INT           the intersection unit is pipelined, one per core: a test issues in INT and the
//                 core goes on after the unit's initiation interval `triangleInterval`, except
//                 after a leaf's last triangle, whose INT waits the unit's `triangleLatency` for
//                 every result of the leaf: the list unit's decision (hit -> OUT, else POP) needs
//                 the leaf's nearest hit (S1 §2.6.10). A leaf of k triangles so spends
//                 (k - 1) interval + latency in INT; its fetches (LIST, UTTM0-2: one memory port,
//                 one state at a time) come between the issues and are not overlapped.
// The defaults, 1, are the golden traversal's one cycle a state, as the BVH core's.

#include <cstdint>

namespace rtu {

struct KdCycles {
  uint32_t boxLatency = 1;
  uint32_t triangleLatency = 1;
  uint32_t triangleInterval = 1;
};

}  // namespace rtu
