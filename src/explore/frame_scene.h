#pragma once
// A run's scene as its core kind reads it (issue 28): the memory image and the host records of the
// camera's frame, chosen once by the kind (`core`, withCoreKind). Every command that runs frames
// (render, fps, sweep and its Slurm tasks, fidelity, --sample) takes its scene from here:
//   svo        the octree (kinds/svo/scene_loader.h) and the frame's t-value records (thesis 8.1),
//              its stack checked against the tree for the timed models;
//   triangles  any other kind: the scene's triangles (loadTriangleScene: a mesh file's, or a voxel
//              scene's faces) built by `accel.builder` into the structure the kind names
//              (buildAccel: `bvh`, `bih`, `kdtree` for the kd kind), then a model header placing
//              them where the SVO frame places the same scene (a voxel scene's faces lie in the
//              octree's cube [-1,1]^3; a mesh file is fitted into it as the voxelizer fits it at
//              `scene.depth`), and the frame's world-space ray records against that header.
// Each kind's scene is its KindScene (explore/kind_scene.h), in its folder:
// kinds/<kind>/explore/.

#include <cstdint>
#include <string>
#include <vector>

#include "config/run_config.h"
#include "geometry/ray.h"
#include "geometry/triangle_mesh.h"
#include "kinds/host_stream.h"
#include "kinds/registry.h"
#include "rtu/model_transform.h"

namespace rtu {

// FrameScene::core of the ray pipe's scene (architecture = raypipe): its k-d image.
inline constexpr const char* kRaypipeSceneCore = "raypipe";

struct FrameScene {
  std::string core;             // the kind it is built for, or kRaypipeSceneCore
  std::vector<uint32_t> words;  // the memory image
  uint32_t entry = 0;           // where a frame's records point: the octree's root, a model header
  std::string name;             // "menger (depth 8)", "bunny.ply"
  std::string description;   // its structure: descriptors and bytes; "binned BVH, 1234 triangles"
  int stackNeeded = 0;       // svo: the stack frames the tree at `entry` needs
  TriangleMesh mesh;         // triangle kinds: the image's triangles in the model's space
  ModelPlacement placement;  // triangle kinds: the model in the world

  WordMemory memory() const { return WordMemory(words); }
};

// Where the SVO frame puts the scene's triangles (loadSceneTriangles'): a mesh file as the
// voxelizer fits it into the octree's cube at spec.depth; a voxel scene's faces, in the cube
// already, where they are.
ModelPlacement framePlacement(const SceneSpec& spec, const TriangleMesh& mesh);

// The world normal of the triangle `primitive` of a triangle kind's scene (its mesh placed by its
// placement), unnormalised, either way round.
glm::dvec3 triangleNormal(const FrameScene& scene, uint32_t primitive);
// Its first corner in the world.
glm::dvec3 triangleCorner(const FrameScene& scene, uint32_t primitive);

// The scene `settings` name for the kind settings.rtu.core, or for the ray pipe
// (explore/raypipe_frame.h: the Tray Racer's k-d image, built or read from accel_file). Throws
// std::invalid_argument for a scene the kind cannot take (an .svo file for a triangle kind) and
// what the loaders and builders throw (a mesh with degenerate or duplicate triangles names
// --drop-bad-triangles).
FrameScene loadFrameScene(const RunConfig& settings);

// Whether `settings` name a recorded workload (a job buffer, `jobs`, or a ray buffer, `rays`)
// instead of the camera's frame.
bool recordedWorkload(const RunConfig& settings);

// The host records of the camera's frame of primary rays on `scene` (in pixel order, id words the
// pixel indices), for its kind; or, for a recorded workload, its buffer's records (a job buffer
// for the SVO kind only: another kind refuses it when the run starts). Throws std::invalid_argument
// when `settings` chooses another kind than the scene's, and, for the SVO kind on a timed model,
// when the tree is deeper than the stack (unless overflow is allowed).
std::vector<HostRecord> frameRecords(const FrameScene& scene, const RunConfig& settings);

// The kind's record of one primary ray (id, world-space ray) on its scene, for the kind named
// `core`: what frameRecords holds for a camera's pixel, made one at a time.
using FrameRecordMaker = HostRecord (*)(const FrameScene& scene, const RunConfig& settings,
                                        uint32_t id, const Ray& ray);
FrameRecordMaker frameRecordMaker(const std::string& core);
// A record of the kind the camera's frame has (its 1x1 frame's), after every check frameRecords
// makes, at the cost of one record: a made RecordSource's sample.
HostRecord frameRecordSample(const FrameScene& scene, const RunConfig& settings);
// The camera's frame as frameRecords holds it, each record made when the run asks for it.
RecordSource frameRecordSource(const FrameScene& scene, const RunConfig& settings);

// What decides which scene is built for a run, as text (the scene, the kind, its build settings):
// runs with the same key share one FrameScene.
std::string frameSceneKey(const RunConfig& settings);

}  // namespace rtu
