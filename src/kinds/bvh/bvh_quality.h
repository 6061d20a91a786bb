#pragma once
// The quality figures (geometry/accel_quality.h) of a BVH's build tree, from its double boxes.

#include "geometry/accel_quality.h"
#include "kinds/bvh/build_tree.h"

namespace rtu {

// All figures but bytes and buildSeconds, which the caller has (the image's size, the build's
// clock). triangles counts the references: each triangle once in a BVH without spatial splits.
// sah uses unit costs, sahSeed `seedCosts` (seed 003: box 1, triangle 2; B8).
AccelQuality measureQuality(const BuildTree& tree, const SahCosts& seedCosts);

}  // namespace rtu
