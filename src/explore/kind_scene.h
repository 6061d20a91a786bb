#pragma once
// Each core kind's scene for a frame (issue 26): what `build --accel` builds for it from triangles,
// and how a frame's scene and host records are made for it (frame_scene.h chooses the kind once,
// withCoreKind). A kind plugs in by specialising KindScene<Kind> in its own folder,
// kinds/<kind>/explore/ (cmake/KindPlugins.cmake includes every header there as
// "kind_explore_plugins.h"), with:
//   kStructure   the name `accel` (build --accel) gives the structure it reads from triangles
//                ("bvh", "kdtree"), or nullptr for a kind built otherwise (svo);
//   build        (kStructure only) that structure from a mesh, as a memory image;
//   load         the frame's scene (FrameScene) under a run's settings;
//   records      the host records of the camera's frame on that scene (its checks, then `record`
//                of each pixel's primary ray);
//   record       the host record of one primary ray (id, world-space ray) on that scene, which a
//                frame streamed as it runs makes when the run asks (app/frame_stream.h);
//   buildKey     the kind's own settings that change its scene (frameSceneKey);
//   passSource   where the frame's secondary passes spawn (PassSource, explore/ray_passes.h): the
//                kind's golden primary hits of the camera's frame, the memory and model header
//                their ray records use, and the kind's way off a surface.
// A triangle kind derives from TriangleKindScene, which builds its structure, puts a model header
// after it and aims the camera's world-space rays at the header; it may hide `accelSpec` (the
// build settings a frame uses) and `appendModelHeader` (its model space) with its own.

#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "explore/accel_build.h"
#include "explore/frame_scene.h"
#include "inputs/camera.h"
#include "inputs/secondary_rays.h"
#include "kinds/core_result.h"
#include "rtu/model_header.h"
#include "run/analytic_run.h"

namespace rtu {

template <class Kind>
struct KindScene;

// Where a frame's secondary passes spawn from on its kind (KindScene<Kind>::passSource).
struct PassSource {
  std::vector<uint32_t> words;   // the memory the passes' ray records run on
  uint32_t modelAddress = 0;     // the model header they point at
  ModelHeader box;               // random rays fill the cube it places (the SVO frame's)
  std::vector<SurfaceHit> hits;  // the golden model's primary hits of the frame, pixel order
  double selfOffset = 0;         // off the surface along the normal (SecondarySettings)
  double gridOffset = 0;         // and along each axis (SecondarySettings)
};

// The host records of the camera's frame by `Scene::record`, in pixel order (ids the pixel
// indices).
template <class Scene>
std::vector<HostRecord> frameRecordsOf(const FrameScene& scene, const RunConfig& settings) {
  const std::vector<Ray> rays = frameRays(settings.camera);
  std::vector<HostRecord> records;
  records.reserve(rays.size());
  for (size_t id = 0; id < rays.size(); ++id)
    records.push_back(Scene::record(scene, settings, static_cast<uint32_t>(id), rays[id]));
  return records;
}

template <class Kind>
struct TriangleKindScene {
  // The structure the frame builds: the run's accel settings, the kind's structure.
  static AccelSpec accelSpec(const RunConfig& settings) {
    AccelSpec spec = settings.accel;
    spec.structure = KindScene<Kind>::kStructure;
    return spec;
  }
  // The model header the frame's records point at, appended after the structure (at word 0): the
  // model's space is the mesh's.
  static uint32_t appendModelHeader(std::vector<uint32_t>& words, const TriangleMesh&,
                                    const ModelPlacement& placement, const RunConfig&) {
    return rtu::appendModelHeader(words, placement, 0);
  }
  static std::string buildKey(const RunConfig&) { return ""; }

  static FrameScene load(const RunConfig& settings) {
    TriangleScene triangles = loadSceneTriangles(settings);
    AccelBuild build =
        buildAccel(triangles.mesh, KindScene<Kind>::accelSpec(settings), settings.rtu);
    FrameScene scene;
    scene.placement = framePlacement(settings.scene, triangles.mesh);
    scene.words = std::move(build.words);
    scene.entry =
        KindScene<Kind>::appendModelHeader(scene.words, triangles.mesh, scene.placement, settings);
    scene.name = triangles.name;
    scene.description = build.description + ", " + std::to_string(triangles.mesh.triangles.size()) +
                        " triangles, " + std::to_string(build.quality.nodes) + " nodes, " +
                        std::to_string(build.quality.bytes) + " bytes";
    scene.mesh = std::move(triangles.mesh);
    return scene;
  }
  static std::vector<HostRecord> records(const FrameScene& scene, const RunConfig& settings) {
    return frameRecordsOf<KindScene<Kind>>(scene, settings);
  }
  // A world-space ray record against the model header.
  static HostRecord record(const FrameScene& scene, const RunConfig&, uint32_t id, const Ray& ray) {
    return makeRayRecord(id, ray, scene.entry);
  }
  // The kind's way off a surface (docs/workloads.md): along the normal, world units. The BVH
  // hides it with none (its span starts at its float epsilon).
  static constexpr double kSelfOffset = 0x1p-12;

  // The golden model's hits of the frame's world-space rays: each where its ray meets the plane
  // of the triangle the kind hit (in float64, in the world: the kind's own surface, to the
  // precision a shader recomputing the point from the triangle has; the BIH's distance, through
  // its grid, is not precise enough for that), with that triangle's world normal toward the ray;
  // the passes' records point at the frame's model header, random rays fill the SVO frame's cube
  // (the world's [-1, 1]^3). The frame is traced as a stream: only the hits are held.
  static PassSource passSource(const FrameScene& scene, const RunConfig& settings) {
    const RecordSource records = frameRecordSource(scene, settings);
    PassSource source;
    traceGolden(scene.memory(), records, settings.rtu,
                [&](uint64_t job, const CoreKindResult& result) {
                  const typename Kind::Result& own = resultOfKind<Kind>(result);
                  if (Kind::hitAhead(own))
                    source.hits.push_back(hitOf(scene, std::get<RayRecord>(records[job]), own));
                });
    source.words = scene.words;
    source.modelAddress = scene.entry;
    source.box = makeModelHeader(ModelPlacement{}, 0);
    source.selfOffset = KindScene<Kind>::kSelfOffset;
    return source;
  }

 private:
  static SurfaceHit hitOf(const FrameScene& scene, const RayRecord& ray,
                          const typename Kind::Result& own) {
    const glm::dvec3 direction(ray.direction[0], ray.direction[1], ray.direction[2]);
    SurfaceHit hit;
    hit.pixel = ray.id;
    hit.incoming = glm::normalize(direction);
    const glm::dvec3 origin(ray.origin[0], ray.origin[1], ray.origin[2]);
    hit.normal = glm::normalize(triangleNormal(scene, own.primitive));
    if (glm::dot(hit.normal, hit.incoming) > 0.0) hit.normal = -hit.normal;
    const glm::dvec3 corner = triangleCorner(scene, own.primitive);
    hit.point = origin +
                glm::dot(corner - origin, hit.normal) / glm::dot(direction, hit.normal) * direction;
    return hit;
  }
};

}  // namespace rtu
