#pragma once
// The k-d kind's frame scene (explore/kind_scene.h): seed 001's k-d tree, PBRT v1's SAH build with
// the Tray Racer's parameters, as the core's memory image and the seed's scene file (`build
// --accel kdtree`); the ray pipe (architecture raypipe) reads the same build.

#include "explore/kind_scene.h"
#include "kinds/kd/kd_kind.h"

namespace rtu {

template <>
struct KindScene<KdKind> : TriangleKindScene<KdKind> {
  static constexpr const char* kStructure = "kdtree";
  static AccelBuild build(const TriangleMesh& mesh, const AccelSpec& spec, const RtuConfig& rtu);
  // The frame does not read the Tray Racer's scene file: its wide form takes any tree (the narrow
  // one refuses past 2^16 nodes).
  static AccelSpec accelSpec(const RunConfig& settings) {
    AccelSpec spec = TriangleKindScene<KdKind>::accelSpec(settings);
    spec.index = "wide";
    return spec;
  }
};

}  // namespace rtu
