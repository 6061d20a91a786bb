#pragma once
// Seed 001's ray pipe as hardware (issue 30 §2; docs/comparison.md, "Resources"): its memories
// and FIFOs at the widths and depths of the RTL (specs/001 §2.2) and its binary32 units, sized by
// the configuration (FIFO depths, ray ids, short stack, traversal units).

#include "raypipe/raypipe_config.h"
#include "rtu/resource_estimate.h"

namespace rtu {

// Memories (depth x bits): the PRG's FIFO (prg x 211), SINT's three (sint x 96, 48, 28), the
// arbiters' (tarb x 96, larb x 37), the block-RAM caches (tcache 512 x 384, lcache 1024 x 256,
// icache 1024 x 288; the set-associative ones add a tag store of half their lines, 2 ways x 20
// bits), a ray store of raysInFlight x 192 for each TRAV, INT and the shader, per TRAV its leaf
// FIFO (travLeaf x 41) and math FIFO (travMath x 144), INT's FIFOs (intList x 129, intLarb x 36,
// intShader x 9), the short stack (shortStackDepth arrays and the restart array of raysInFlight x
// 48), the shader's ray id and pixel id arrays (raysInFlight x 9, x 19) and the pixel buffer
// (pixelBuffer x 35).
// Units (binary32): the PRG's 11 multipliers and 8 adders (its direction U a + V b + 240 W and
// the pixel offsets), SINT's 2 adders, 2 dividers and 5 comparators, per TRAV an adder, a divider
// and 3 comparators, INT's 20 multipliers, 18 adders, a divider and 3 comparators, and the
// short stack's and list unit's comparator each.
ResourceEstimate raypipeResources(const RaypipeConfig& config);

}  // namespace rtu
