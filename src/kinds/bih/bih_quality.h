#pragma once
// The quality figures (geometry/accel_quality.h) of a BIH build. A BIH node's box is its clipped
// interval: the scene box [0, sceneUpper] cut, on each ancestor's axis, to the left child's
// [.., clip0] or the right child's [clip1, ..]; that is the region a traversal keeps a ray's
// [tmin, tmax] in, so the SAH weighs those boxes (grid units; the ratio to the root's area has
// none).

#include "geometry/accel_quality.h"
#include "kinds/bih/bih_builder.h"

namespace rtu {

// All figures but bytes and buildSeconds, which the caller has. triangles counts the distinct
// triangle numbers listed, listEntries the list's words; sah = (Σ_inner A + Σ_leaf A·n)/A_root with
// the clipped boxes; sahSeed is NaN: seed 004 gives no SAH figure.
AccelQuality measureQuality(const BihBuild& build, const GridPoint& sceneUpper);

}  // namespace rtu
