#pragma once
// The quality figures (geometry/accel_quality.h) of a k-d tree build. A node's box is its cell:
// the build's bounds cut by each ancestor's split plane, the region it covers; a triangle listed
// in several leaves counts in each.

#include "geometry/accel_quality.h"
#include "kinds/kd/pbrt_kd_builder.h"

namespace rtu {

// All figures but bytes and buildSeconds, which the caller has. triangles counts the distinct
// triangles listed, listEntries the lists' length, emptyLeaves the leaves with no triangle;
// sah = (Σ_inner A + Σ_leaf A·n)/A_root over the cells, sahSeed the same with PBRT's costs as the
// build used them (`parameters`: traversal 1, intersection 80 for the Tray Racer).
AccelQuality measureQuality(const KdBuild& build, const PbrtKdParameters& parameters);

}  // namespace rtu
