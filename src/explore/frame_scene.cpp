#include "explore/frame_scene.h"

#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>

#include "explore/kind_scene.h"
#include "explore/raypipe_frame.h"
#include "inputs/host_buffers.h"
#include "kind_explore_plugins.h"
#include "kinds/svo/mesh_voxelizer.h"

namespace rtu {
namespace {

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

glm::dvec3 triangleNormal(const FrameScene& scene, uint32_t primitive) {
  const auto& corners = scene.mesh.triangles.at(primitive);
  const glm::dvec3 a = scene.mesh.vertices[corners[0]], b = scene.mesh.vertices[corners[1]],
                   c = scene.mesh.vertices[corners[2]];
  // A normal maps to the world by R S^-1 (the inverse transpose of R S).
  return scene.placement.rotation * (glm::cross(b - a, c - a) / scene.placement.scale);
}

glm::dvec3 triangleCorner(const FrameScene& scene, uint32_t primitive) {
  const ModelPlacement& p = scene.placement;
  return p.rotation * (p.scale * scene.mesh.vertices[scene.mesh.triangles.at(primitive)[0]]) +
         p.translation;
}

FrameScene loadFrameScene(const RunConfig& settings) {
  if (settings.architecture == Architecture::Raypipe) return raypipeFrameScene(settings);
  FrameScene scene = withCoreKind(settings.rtu.core, [&settings](auto kind) {
    return KindScene<decltype(kind)>::load(settings);
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
    return KindScene<decltype(kind)>::records(scene, settings);
  });
}

FrameRecordMaker frameRecordMaker(const std::string& core) {
  return withCoreKind(core, [](auto kind) -> FrameRecordMaker {
    return &KindScene<decltype(kind)>::record;
  });
}

HostRecord frameRecordSample(const FrameScene& scene, const RunConfig& settings) {
  RunConfig onePixel = settings;
  onePixel.camera.width = onePixel.camera.height = 1;
  settings.camera.validate();
  return frameRecords(scene, onePixel).front();
}

RecordSource frameRecordSource(const FrameScene& scene, const RunConfig& settings) {
  const FrameRecordMaker make = frameRecordMaker(settings.rtu.core);
  return RecordSource(
      settings.camera.pixelCount(),
      [&scene, &settings, make](uint64_t index) {
        return make(scene, settings, static_cast<uint32_t>(index), settings.camera.pixelRay(index));
      },
      frameRecordSample(scene, settings));
}

std::string frameSceneKey(const RunConfig& settings) {
  const SceneSpec& spec = settings.scene;
  const AccelSpec& accel = settings.accel;
  const std::string pipe = settings.architecture == Architecture::Raypipe
                               ? std::string(kRaypipeSceneCore) + "|" + accel.file + "|"
                               : std::string();
  const std::string kindKey = withCoreKind(settings.rtu.core, [&](auto kind) {
    return KindScene<decltype(kind)>::buildKey(settings);
  });
  return pipe + settings.rtu.core + "|" + spec.procedural + "|" + spec.svoFile + "|" +
         spec.meshFile + "|" + spec.binvoxFile + "|" + std::to_string(spec.depth) + "|" +
         std::to_string(spec.seed) + "|" + std::to_string(spec.root) + "|" +
         std::to_string(spec.maxDepth) + "|" + accel.builder + "|" +
         std::to_string(accel.dropBadTriangles) + "|" + kindKey + "|" + accel.index + "|" +
         accel.kdEdgeOrder + "|" + accel.kdMatrix;
}

}  // namespace rtu
