#pragma once
// `rtusim build` for the triangle structures (issue 27): the scene's triangles built into a BVH
// (seed 003, any of its builders), a BIH (seed 004, on its n-bit grid) or a k-d tree (seed 001,
// PBRT v1's SAH build), laid out as the memory image a core reads, with the structure's quality
// figures; the k-d tree also as the Tray Racer's own scene file.

#include <string>
#include <utility>
#include <vector>

#include "config/run_config.h"
#include "geometry/accel_quality.h"
#include "geometry/triangle_mesh.h"
#include "kinds/svo/scene_loader.h"

namespace rtu {

struct AccelBuild {
  std::vector<uint32_t> words;        // the memory image, its header first
  std::vector<uint8_t> sceneFile;     // kdtree: the Tray Racer's scene file
  AccelQuality quality;               // bytes and build_seconds included
  std::string description;            // "binned BVH", "BIH (c99 formats, seed indices)"
  std::vector<std::string> warnings;  // a seed's capacities exceeded
  // The build's own settings for `build --stats` ("builder": "binned"), in their order.
  std::vector<std::pair<std::string, std::string>> settings;
};

// The structure spec.structure names, built by the kind that reads it (KindScene<Kind>::build,
// explore/kind_scene.h) under that kind's settings in `rtu` (the BIH's number formats). Throws
// std::invalid_argument for a name no kind builds, and what the builders and layouts throw (a
// capacity a format cannot hold names it).
AccelBuild buildAccel(const TriangleMesh& mesh, const AccelSpec& spec,
                      const RtuConfig& rtu = RtuConfig{});

// The names of the structures buildAccel builds, as "bvh, bih or kdtree".
std::string accelStructureNames();

// The scene's triangles under the settings' mesh-defect policy (accel.drop_bad_triangles); a
// droppable defect refused is a std::runtime_error saying how to drop it.
TriangleScene loadSceneTriangles(const RunConfig& settings);

}  // namespace rtu
