#pragma once
// The cycles of the BVH core's states (issue 28): a memory state (a 4-word access) and the
// bookkeeping states take one cycle; the box tests and the triangle test take their unit's.
//   ROOT_TEST, DECIDE  `boxLatency` each: the box unit tests a node's two children at once, as
//                      the seed tests both children at the parent (DECIDE), or the root (ROOT_TEST)
//   TEST               the triangle unit is pipelined, one unit per core: a test issues in TEST and
//                      the core goes on after the unit's initiation interval `triangleInterval`,
//                      except after the leaf's last test, whose TEST waits the unit's
//                      `triangleLatency` for every result of the leaf (its nearest hit decides
//                      what POP skips). A leaf of k triangles so spends (k-1) interval + latency in
//                      TEST; its fetches (REF, TRI0-2: one memory port, one state at a time) come
//                      between the issues and are not overlapped.
//   XFORM              `transformLatency`: a two-level BVH's move of the ray into an instance's
//                      mesh space (rtu/model_transform.h: a subtract, three rounds of multiply and
//                      add, a scale), one pipelined unit per core as the job manager's ray stages
// Seed 004's unit takes 41 cycles at one test a cycle; the defaults, 1, are the golden
// traversal's one cycle a state. docs/cycle-semantics.md, "The BVH core", works a leaf out.

#include <cstdint>

namespace rtu {

struct BvhCycles {
  uint32_t boxLatency = 1;
  uint32_t triangleLatency = 1;
  uint32_t triangleInterval = 1;
  uint32_t transformLatency = 1;
};

}  // namespace rtu
