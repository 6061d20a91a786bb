#pragma once
// `rtusim render --core bvh` (issue 28): the scene's triangles (loadTriangleScene: a mesh file's,
// or a voxel scene's faces) built by `accel.builder` into a BVH image, with a model header placing
// them where the SVO render places the same scene, so that the same camera frames both alike: a
// voxel scene's faces lie in the octree's cube [-1,1]^3 already; a mesh file is fitted into it as
// the voxelizer fits it at `scene.depth` (kinds/svo/mesh_voxelizer.h). The frame's rays are
// world-space ray records against that header, traced by the chosen model; the images come from
// the results and the mesh's triangle normals.

#include <cstdint>
#include <string>
#include <vector>

#include "app/frame_images.h"
#include "config/run_config.h"
#include "geometry/triangle_mesh.h"
#include "kinds/bvh/bvh_kind.h"
#include "rtu/model_transform.h"

namespace rtu {

struct BvhScene {
  TriangleMesh mesh;              // in the model's space, the image's triangles
  ModelPlacement placement;       // the model in the world
  std::vector<uint32_t> words;    // the image at word 0, then the model header
  uint32_t header = 0;            // the model header's word address
  std::string name, description;  // the scene; "binned BVH, 1234 triangles, ..."
};

// Throws as loadTriangleScene and buildAccel (a mesh with degenerate or duplicate triangles names
// --drop-bad-triangles).
BvhScene loadBvhScene(const RunConfig& settings);

// The frame's pixels from results whose id words are pixel indices; the normal of each hit
// triangle in the world.
RenderedFrame bvhFrame(const Camera& camera, const BvhScene& scene,
                       const std::vector<BvhResult>& results);

// Hits, mean cost and the BVH counters of a frame's results, as report lines.
std::string describeBvhResults(const std::vector<BvhResult>& results);

}  // namespace rtu
