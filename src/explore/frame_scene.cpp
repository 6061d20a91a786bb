#include "explore/frame_scene.h"

#include <stdexcept>
#include <utility>

#include "explore/accel_build.h"
#include "explore/raypipe_frame.h"
#include "geometry/ray_sets.h"
#include "inputs/camera.h"
#include "inputs/host_buffers.h"
#include "kinds/bih/bih_config.h"
#include "kinds/bih/bih_model.h"
#include "kinds/svo/mesh_voxelizer.h"
#include "kinds/svo/scene_loader.h"
#include "kinds/svo/stack_check.h"
#include "kinds/svo/svo_validator.h"
#include "rtu/model_header.h"

namespace rtu {
namespace {

// The model header a triangle kind's frame reads, appended after its structure (at word 0): the
// BVH's model space is the mesh's; the BIH's is the grid `format` puts the mesh on (bih_model.h).
template <class Kind>
uint32_t appendFrameModelHeader(std::vector<uint32_t>& words, const TriangleMesh&,
                                const ModelPlacement& placement, const RunConfig&) {
  return appendModelHeader(words, placement, 0);
}

template <>
uint32_t appendFrameModelHeader<BihKind<>>(std::vector<uint32_t>& words, const TriangleMesh& mesh,
                                           const ModelPlacement& placement,
                                           const RunConfig& settings) {
  const SceneGrid grid(meshBounds(mesh), settings.rtu.coreConfig<BihKind<>>().format);
  return appendBihModelHeader(words, grid, placement);
}

// What buildAccel builds for a triangle kind: the structure of the kind's name, with the run's
// accel settings. The k-d core's is `build --accel kdtree`'s, whose Tray Racer scene file the
// frame does not read: its wide form takes any tree (the narrow one refuses past 2^16 nodes).
template <class Kind>
AccelSpec frameAccelSpec(const RunConfig& settings) {
  AccelSpec spec = settings.accel;
  spec.structure = Kind::kName;
  return spec;
}

template <>
AccelSpec frameAccelSpec<KdKind>(const RunConfig& settings) {
  AccelSpec spec = settings.accel;
  spec.structure = "kdtree";
  spec.index = "wide";
  return spec;
}

// A triangle kind's scene: buildAccel's structure of the kind, a model header after it, the
// frame's world-space ray records against the header.
template <class Kind>
struct FrameSceneOf {
  static FrameScene load(const RunConfig& settings) {
    TriangleScene triangles = loadSceneTriangles(settings);
    AccelBuild build = buildAccel(triangles.mesh, frameAccelSpec<Kind>(settings),
                                  settings.rtu.coreConfig<BihKind<>>().format);
    FrameScene scene;
    scene.placement = framePlacement(settings.scene, triangles.mesh);
    scene.words = std::move(build.words);
    scene.entry =
        appendFrameModelHeader<Kind>(scene.words, triangles.mesh, scene.placement, settings);
    scene.name = triangles.name;
    scene.description = build.description + ", " + std::to_string(triangles.mesh.triangles.size()) +
                        " triangles, " + std::to_string(build.quality.nodes) + " nodes, " +
                        std::to_string(build.quality.bytes) + " bytes";
    scene.mesh = std::move(triangles.mesh);
    return scene;
  }
  static std::vector<HostRecord> records(const FrameScene& scene, const RunConfig& settings) {
    const std::vector<RayRecord> rays = makeFrameRayRecords(settings.camera, scene.entry);
    return {rays.begin(), rays.end()};
  }
};

// The SVO kind's: the octree and t-value records.
template <>
struct FrameSceneOf<SvoKind> {
  static FrameScene load(const RunConfig& settings) {
    // A deep build takes minutes: refused before it.
    checkBuiltSceneFitsStack(settings.scene, settings.rtu.coreConfig<SvoKind>().stackFrames,
                             settings.allowStackOverflow);
    Scene built = loadScene(settings.scene);
    FrameScene scene;
    scene.stackNeeded = descriptorDepths(built.image, {built.image.root}).front();
    scene.words = std::move(built.image.words);
    scene.entry = built.image.root;
    scene.name = std::move(built.name);
    scene.description = std::move(built.summary);
    return scene;
  }
  static std::vector<HostRecord> records(const FrameScene& scene, const RunConfig& settings) {
    checkNeededFrames({scene.entry}, {scene.stackNeeded},
                      settings.rtu.coreConfig<SvoKind>().stackFrames, settings.allowStackOverflow,
                      sceneSource(settings.scene));
    const std::vector<TValueRecord> jobs =
        makeFrameJobs(settings.camera, scene.entry, settings.epsilon);
    return {jobs.begin(), jobs.end()};
  }
};

// The ray pipe's (raypipe_frame.h): its k-d image, built from the scene's triangles or read from
// accel_file (a k-d image or the seed's scene file). Its rays are the PRG's, made by its rows.
FrameScene raypipeFrameScene(const RunConfig& settings) {
  RaypipeScene pipe = loadRaypipeScene(settings, settings.accel.file);
  FrameScene scene;
  scene.core = kRaypipeSceneCore;
  scene.words = std::move(pipe.image);
  scene.name = std::move(pipe.name);
  scene.description = std::move(pipe.description);
  return scene;
}

}  // namespace

ModelPlacement framePlacement(const SceneSpec& spec, const TriangleMesh& mesh) {
  ModelPlacement placement;
  if (spec.meshFile.empty()) return placement;  // voxel faces: in the cube already
  const MeshVoxelizer fit(mesh, spec.depth);
  placement.translation = fit.offset();
  placement.scale = glm::dvec3(fit.scale());
  return placement;
}

FrameScene loadFrameScene(const RunConfig& settings) {
  if (settings.architecture == Architecture::Raypipe) return raypipeFrameScene(settings);
  FrameScene scene = withCoreKind(settings.rtu.core, [&settings](auto kind) {
    return FrameSceneOf<decltype(kind)>::load(settings);
  });
  scene.core = settings.rtu.core;
  return scene;
}

// A recorded workload: the records of the job buffer (`jobs`) or ray buffer (`rays`), read whole;
// a record with impossible values is an error naming the buffer and the record.
std::vector<HostRecord> recordedRecords(const RunConfig& settings) {
  if (!settings.jobs.empty() && !settings.rays.empty())
    throw std::invalid_argument("jobs excludes rays: give one recorded workload");
  if (!settings.jobs.empty()) {
    const std::vector<TValueRecord> jobs = readJobBuffer(settings.jobs);
    return {jobs.begin(), jobs.end()};
  }
  const std::vector<RayRecord> rays = readRayBuffer(settings.rays);
  return {rays.begin(), rays.end()};
}

bool recordedWorkload(const RunConfig& settings) {
  return !settings.jobs.empty() || !settings.rays.empty();
}

std::vector<HostRecord> frameRecords(const FrameScene& scene, const RunConfig& settings) {
  if (settings.rtu.core != scene.core)
    throw std::invalid_argument("a scene built for the " + scene.core + " core cannot run on the " +
                                settings.rtu.core + " core");
  if (recordedWorkload(settings)) return recordedRecords(settings);
  return withCoreKind(scene.core, [&](auto kind) {
    return FrameSceneOf<decltype(kind)>::records(scene, settings);
  });
}

std::string frameSceneKey(const RunConfig& settings) {
  const SceneSpec& spec = settings.scene;
  const AccelSpec& accel = settings.accel;
  const std::string pipe = settings.architecture == Architecture::Raypipe
                               ? std::string(kRaypipeSceneCore) + "|" + accel.file + "|"
                               : std::string();
  return pipe + settings.rtu.core + "|" + spec.procedural + "|" + spec.svoFile + "|" +
         spec.meshFile + "|" + spec.binvoxFile + "|" + std::to_string(spec.depth) + "|" +
         std::to_string(spec.seed) + "|" + std::to_string(spec.root) + "|" +
         std::to_string(spec.maxDepth) + "|" + accel.builder + "|" +
         std::to_string(accel.dropBadTriangles) + "|" +
         bihFormatName(settings.rtu.coreConfig<BihKind<>>().format) + "|" + accel.index + "|" +
         accel.kdEdgeOrder;
}

}  // namespace rtu
