#pragma once
// The SVO kind's frame scene (explore/kind_scene.h): the octree (scene_loader.h: built from a
// procedural scene, a mesh or a binvox file, or read from an .svo file) and the frame's t-value
// records (thesis 8.1), its stack checked against the tree. It builds no structure from triangles
// (`build --accel svo` voxelises them).

#include <string>
#include <vector>

#include "explore/kind_scene.h"
#include "kinds/svo/svo_kind.h"

namespace rtu {

template <>
struct KindScene<SvoKind> {
  static constexpr const char* kStructure = nullptr;
  static FrameScene load(const RunConfig& settings);
  static std::vector<HostRecord> records(const FrameScene& scene, const RunConfig& settings);
  // The thesis' t-value record of the ray against the octree (its entry).
  static HostRecord record(const FrameScene& scene, const RunConfig& settings, uint32_t id,
                           const Ray& ray);
  static std::string buildKey(const RunConfig&) { return ""; }
  // The golden model's hits of the frame's rays as ray records against a model header appended
  // after the octree (the identity placement: the cube where the frame's t-value records see
  // it), which the passes' records point at; off a surface 16 steps of the format along the
  // normal (the golden t is within a few steps of the exact one), past the hit voxel's exit.
  static PassSource passSource(const FrameScene& scene, const RunConfig& settings);
};

}  // namespace rtu
