#pragma once
// The BVH kind's frame scene (explore/kind_scene.h): seed 003's BVH built by `accel.builder`
// (binned or sweep SAH, Langr's, LBVH), in the mesh's model space.

#include "explore/kind_scene.h"
#include "kinds/bvh/bvh_kind.h"

namespace rtu {

template <>
struct KindScene<BvhKind<>> : TriangleKindScene<BvhKind<>> {
  static constexpr const char* kStructure = "bvh";
  // No offset off a surface: a spawned ray's span starts at kBvhSpanTMin, the float epsilon.
  static constexpr double kSelfOffset = 0;
  static AccelBuild build(const TriangleMesh& mesh, const AccelSpec& spec, const RtuConfig& rtu);
};

}  // namespace rtu
