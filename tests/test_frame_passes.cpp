// A frame's secondary passes on every core kind (explore/ray_passes.h, issue 32): each kind spawns
// them from its own golden hits (KindScene<Kind>::passSource), equal to a float64 spawn from the
// triangle oracle's hits; and the passes run as one workload behind the primary rays, their
// statistics windows of that run summing to the frame's.

#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "explore/frame_scene.h"
#include "explore/ray_passes.h"
#include "geometry/triangle_oracle.h"
#include "inputs/camera.h"
#include "run/model_run.h"

namespace rtu {
namespace {

RunConfig passFrame(const std::string& core) {
  RunConfig settings;
  settings.rtu.core = core;
  settings.scene.procedural = "menger";
  settings.scene.depth = 3;
  settings.camera.width = 40;
  settings.camera.height = 24;
  settings.accel.index = "wide";
  // R1's matrices are singular for this scene's outer faces (docs/triangles.md, "Faces on the
  // scene box and flat triangles"): the k-d tree finds them with the normal's column.
  settings.accel.kdMatrix = "normal";
  return settings;
}

glm::dvec3 vec(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }

// The float64 spawn of each pixel's hit from the oracle's nearest hit of the camera's ray on the
// scene's triangles (a voxel scene's faces, in the world where they are): the point and the
// face's unit normal toward the ray.
struct ReferenceHit {
  glm::dvec3 point, normal;
};

std::vector<std::optional<ReferenceHit>> referenceHits(const FrameScene& scene,
                                                       const Camera& camera) {
  std::vector<std::optional<ReferenceHit>> hits;
  for (const Ray& ray : frameRays(camera)) {
    const std::optional<OracleHit> hit = closestHit(scene.mesh, ray, 0.0, INFINITY);
    if (!hit) {
      hits.emplace_back();
      continue;
    }
    glm::dvec3 normal = glm::normalize(triangleNormal(scene, hit->triangle));
    if (glm::dot(normal, ray.direction) > 0) normal = -normal;
    hits.push_back(ReferenceHit{ray.origin + hit->t * ray.direction, normal});
  }
  return hits;
}

}  // namespace

TEST_CASE("Each triangle kind's shadow rays are its own hits' spawn\\, a float64 spawn's within "
          "float precision",
          "[passes]") {
  // The passes spawn from the kind's golden hits: every pixel the float64 oracle hits is a hit of
  // the kind, at the oracle's point (the kind's float or fixed-point t) and with its face's
  // normal; the shadow ray starts the kind's offset out along it and ends at the light.
  for (const std::string core : {"bvh", "bih", "kd"}) {
    INFO(core);
    RunConfig settings = passFrame(core);
    settings.model = ModelKind::Golden;
    const FrameScene scene = loadFrameScene(settings);
    const PassSource source = framePassSource(scene, settings);
    const std::vector<std::optional<ReferenceHit>> reference =
        referenceHits(scene, settings.camera);
    size_t oracleHits = 0;
    for (const auto& hit : reference) oracleHits += hit.has_value();
    CHECK(oracleHits > 200);
    CHECK(source.hits.size() == oracleHits);
    const FramePassesRun run =
        runFramePasses(scene, settings, {RayType::Primary, RayType::Shadow}, std::nullopt);
    const std::vector<RayRecord>& shadow = run.passes.at(0).rays;
    const glm::dvec3 light = settings.workload.secondary.lights.front().position;
    size_t checked = 0, occluded = 0, agree = 0;
    double worstOrigin = 0, worstDirection = 0;
    for (size_t i = 0; i < shadow.size(); ++i) {
      const RayRecord& ray = shadow[i];
      REQUIRE(ray.span == RaySpan::AnyHit);
      REQUIRE(ray.modelAddress == scene.entry);
      const std::optional<ReferenceHit>& hit = reference.at(ray.id);
      REQUIRE(hit.has_value());
      const glm::dvec3 origin = hit->point + source.selfOffset * hit->normal;
      const double originError = glm::length(vec(ray.origin) - origin);
      const double directionError = glm::length(vec(ray.direction) - (light - origin));
      ++checked;
      occluded += run.passes[0].hits[i];
      if (originError > 1e-3) continue;  // counted below: every spawn must be the oracle's
      ++agree;
      worstOrigin = std::max(worstOrigin, originError);
      worstDirection = std::max(worstDirection, directionError);
    }
    INFO(checked << " shadow rays, " << occluded << " occluded, " << agree
                 << " from the oracle's surface; origins within " << worstOrigin
                 << ", directions within " << worstDirection);
    CHECK(checked > 80);
    CHECK(occluded < checked);
    CHECK(agree == checked);
    // float32 records of points about 2 from the origin (2^-23 relative)
    CHECK(worstOrigin < 1e-6);
    CHECK(worstDirection < 2e-6);
  }
}

TEST_CASE("A frame's passes are one run whose windows sum to the frame's statistics", "[passes]") {
  // Primary, shadow and AO rays as one job stream on the timed models: the frame's rays are all
  // of them, and the primary run's statistics with each pass's window (the run up to the pass
  // less the run before it) give the frame's rays, cycles and counters; the passes' hits are the
  // golden model's.
  for (const std::string core : {"svo", "bvh"}) {
    for (const ModelKind model : {ModelKind::CycleAccurate, ModelKind::LooselyTimed}) {
      INFO(core << " on " << toString(model));
      RunConfig settings = passFrame(core);
      settings.model = model;
      settings.rtu.memory = MemoryConfig{};  // caches and DRAM: counters to sum
      settings.workload.secondary.samples = 2;
      const FrameScene scene = loadFrameScene(settings);
      const RtuStatistics primary =
          runModel(model, scene.memory(), frameRecords(scene, settings), settings.rtu).statistics;
      const std::vector<RayType> passes{RayType::Primary, RayType::Shadow, RayType::Ao};
      const FramePassesRun run = runFramePasses(scene, settings, passes, primary);
      REQUIRE(run.frame.has_value());
      REQUIRE(run.passes.size() == 2);
      uint64_t rays = primary.rays, cycles = primary.totalCycles;
      uint64_t dram = primary.l2.dram.bytes, l1Hits = primary.allL1().hits;
      for (const PassRun& pass : run.passes) {
        REQUIRE(pass.statistics.has_value());
        CHECK(pass.statistics->rays == pass.rays.size());
        CHECK(pass.statistics->totalCycles > 0);
        rays += pass.statistics->rays;
        cycles += pass.statistics->totalCycles;
        dram += pass.statistics->l2.dram.bytes;
        l1Hits += pass.statistics->allL1().hits;
      }
      CHECK(run.frame->rays == 960 + run.passes[0].rays.size() + run.passes[1].rays.size());
      CHECK(rays == run.frame->rays);
      CHECK(cycles == run.frame->totalCycles);
      CHECK(dram == run.frame->l2.dram.bytes);
      CHECK(l1Hits == run.frame->allL1().hits);
      CHECK(dram > 0);
      RunConfig golden = settings;
      golden.model = ModelKind::Golden;
      const FramePassesRun untimed = runFramePasses(scene, golden, passes, std::nullopt);
      for (size_t p = 0; p < 2; ++p) CHECK(untimed.passes[p].hits == run.passes[p].hits);
    }
  }
}

}  // namespace rtu
