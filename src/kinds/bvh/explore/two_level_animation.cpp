#include "kinds/bvh/explore/two_level_animation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include <glm/geometric.hpp>

#include "explore/accel_build.h"
#include "explore/animation_frame_columns.h"
#include "explore/scene_mesh.h"
#include "kinds/bvh/bvh_quality.h"
#include "kinds/core_result.h"
#include "run/rtu_simulation.h"

namespace rtu {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TwoLevelBvh buildMeshes(const std::vector<TriangleMesh>& meshes, const AccelSpec& spec,
                        const RtuConfig& rtu, std::vector<double>& seconds) {
  std::vector<MeshBvh> built;
  for (const TriangleMesh& mesh : meshes) {
    const AccelBuild build = buildAccel(mesh, spec, rtu);
    seconds.push_back(build.quality.buildSeconds);
    built.push_back(meshBvh(BvhImage{build.words}));
  }
  return TwoLevelBvh(std::move(built));
}

// The meshes' images laid out once, beside the structure.
TwoLevelWorkspace workspaceOver(TwoLevelBvh bvh) {
  TwoLevelImage image(bvh);
  return TwoLevelWorkspace{std::move(bvh), std::move(image)};
}

std::vector<TriangleMesh> loadMeshes(const SceneDescription& scene) {
  std::vector<TriangleMesh> meshes;
  for (const ModelDescription& model : scene.models) meshes.push_back(sceneModelMesh(model));
  return meshes;
}

AccelSpec bvhSpec(AccelSpec spec) {
  spec.structure = "bvh";
  return spec;
}

const RtuConfig& checkedBvh(const RtuConfig& rtu) {
  if (rtu.core != BvhKind<>::kName)
    throw std::invalid_argument("the two-level BVH runs on the bvh core, not " + rtu.core);
  return rtu;
}

}  // namespace

const StatisticGroup<TwoLevelFrameStatistics>& TwoLevelFrameStatistics::declaration() {
  using F = TwoLevelFrameStatistics;
  static const StatisticGroup<F> group = withFrameTime(
      animationFrameColumns<F>("a frame of a two-level BVH animation: the columns of animate's CSV")
          .count(Statistic("pixels", "pixels", "the frame's pixels, one ray each"), &F::pixels)
          .count(Statistic("hits", "rays", "pixels whose ray hit an instance"), &F::hits)
          .count(Statistic("instances", "instances", "instances placed in the frame"),
                 &F::instances)
          .real(Statistic("top_build_s", "s",
                          "the top level's build over the instances' world boxes, wall clock"),
                &F::topBuildSeconds)
          .count(Statistic("top_nodes", "nodes", "the top level's nodes"), &F::topNodes)
          .real(Statistic("top_sah", "", "the top level's SAH, unit costs"), &F::topSah)
          .real(Statistic("top_sah_seed", "", "the top level's SAH, seed 003's costs"),
                &F::topSahSeed)
          .count(Statistic("instances_entered", "instances",
                           "instances the rays entered (XFORM states): the run's bvh_instances"),
                 &F::instancesEntered)
          .derived(Statistic("instances_per_ray", "instances", "instances entered per ray"),
                   &F::instancesPerRay)
          .count(Statistic("nodes_visited", "nodes", "node records fetched, both levels"),
                 &F::nodesVisited)
          .count(Statistic("triangle_tests", "tests", "ray/triangle tests"), &F::triangleTests)
          .count(Statistic("traversal_cycles", "cycles", "the rays' costs summed"),
                 &F::traversalCycles));
  return group;
}

TwoLevelAnimation::TwoLevelAnimation(const SceneDescription& scene,
                                     TwoLevelAnimationOptions options)
    : scene_(scene),
      options_(std::move(options)),
      meshes_(loadMeshes(scene)),
      workspace_(workspaceOver(
          buildMeshes(meshes_, bvhSpec(options_.accel), checkedBvh(options_.rtu), meshSeconds_))) {
  uint32_t base = 0;
  for (const InstanceDescription& instance : scene.instances) {
    primitiveBases_.push_back(base);
    base += static_cast<uint32_t>(meshes_.at(instance.model).triangles.size());
  }
}

std::vector<BvhInstance> TwoLevelAnimation::placements(double time) const {
  std::vector<BvhInstance> instances;
  for (const InstanceDescription& instance : scene_.instances)
    instances.push_back(
        BvhInstance{static_cast<uint32_t>(instance.model), instance.placement.at(time)});
  return instances;
}

TwoLevelFrame TwoLevelAnimation::render(int frame) { return render(frame, workspace_); }

TwoLevelFrame TwoLevelAnimation::render(int frame, TwoLevelWorkspace& workspace) const {
  const auto start = std::chrono::steady_clock::now();
  const double time = scene_.timeOf(frame);
  TwoLevelFrame out;
  TwoLevelFrameStatistics& statistics = out.statistics;
  out.instances = placements(time);
  TwoLevelBvh& bvh = workspace.bvh;
  std::vector<BvhInstance> instances = out.instances;
  const auto buildStart = std::chrono::steady_clock::now();
  bvh.place(std::move(instances));
  statistics.topBuildSeconds = secondsSince(buildStart);
  workspace.image.writeFrame(bvh);
  const AccelQuality quality = measureQuality(bvh.topLevel().tree, SahCosts{1.0, 2.0});
  statistics.topNodes = quality.nodes;
  statistics.topSah = quality.sah;
  statistics.topSahSeed = quality.sahSeed;
  out.camera = scene_.camera.at(time, scene_.width, scene_.height);
  const std::vector<RayRecord> rays =
      makeFrameRayRecords(out.camera, workspace.image.worldHeader());
  const RtuRun run = runModel(options_.model, workspace.image.memory(),
                              std::vector<HostRecord>(rays.begin(), rays.end()), options_.rtu);
  out.results = resultsOfKind<BvhKind<>>(resultsInJobOrder(run));
  for (const BvhResult& result : out.results) statistics.hits += result.hit;
  // The cores' counters (bvh_counters.h), as the run's statistics JSON has them.
  const CoreStatistics cores = run.statistics.allCores();
  statistics.instancesEntered = cores.bvhInstances;
  statistics.nodesVisited = cores.bvhNodesVisited;
  statistics.triangleTests = cores.bvhTriangleTests;
  statistics.traversalCycles = cores.busyCycles;
  statistics.frame = frame;
  statistics.time = time;
  statistics.pixels = rays.size();
  statistics.instances = scene_.instances.size();
  statistics.cycles = run.totalCycles;
  statistics.clockMhz = options_.rtu.clockMhz;
  statistics.hostSeconds = secondsSince(start);
  return out;
}

void TwoLevelAnimation::renderFrames(int threads,
                                     const std::function<void(const TwoLevelFrame&)>& take) {
  if (threads > 1 && options_.model != ModelKind::Golden)
    throw std::invalid_argument(std::string("frames in parallel threads (--threads) need the "
                                            "golden model, not ") +
                                toString(options_.model));
  const int count = std::max(1, std::min(threads, scene_.frames));
  std::vector<TwoLevelWorkspace> copies(static_cast<size_t>(count - 1), workspace_);
  for (int first = 0; first < scene_.frames; first += count) {
    std::vector<TwoLevelFrame> frames(static_cast<size_t>(std::min(count, scene_.frames - first)));
    std::vector<std::exception_ptr> errors(frames.size());
    const auto renderOne = [&](size_t i, TwoLevelWorkspace& workspace) {
      try {
        frames[i] = render(first + static_cast<int>(i), workspace);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    };
    std::vector<std::thread> pool;
    for (size_t i = 1; i < frames.size(); ++i)
      pool.emplace_back([&renderOne, &copies, i] { renderOne(i, copies[i - 1]); });
    renderOne(0, workspace_);
    for (std::thread& thread : pool) thread.join();
    for (const std::exception_ptr& error : errors)
      if (error) std::rethrow_exception(error);
    for (const TwoLevelFrame& frame : frames) take(frame);
  }
}

size_t TwoLevelAnimation::instanceOf(uint32_t primitive) const {
  return static_cast<size_t>(
      std::upper_bound(primitiveBases_.begin(), primitiveBases_.end(), primitive) -
      primitiveBases_.begin() - 1);
}

glm::dvec3 TwoLevelAnimation::worldNormal(const TwoLevelFrame& frame, int x, int y,
                                          const BvhResult& hit) const {
  const size_t instance = instanceOf(hit.primitive);
  const BvhInstance& placed = frame.instances.at(instance);
  const TriangleMesh& mesh = meshes_.at(placed.mesh);
  const auto& triangle = mesh.triangles.at(hit.primitive - primitiveBases_[instance]);
  const glm::dvec3 a = mesh.vertices[triangle[0]], b = mesh.vertices[triangle[1]],
                   c = mesh.vertices[triangle[2]];
  const ModelPlacement& p = placed.placement;
  // Normals go through the inverse transpose of R S, which is R S^-1.
  const glm::dvec3 normal = p.rotation * (glm::cross(b - a, c - a) / p.scale);
  const double length = glm::length(normal);
  if (!(length > 0)) return glm::dvec3(0.0);  // a degenerate triangle: lit by the sky only
  const glm::dvec3 direction = frame.camera.primaryRay(x, y).direction;
  return glm::dot(normal, direction) > 0.0 ? -normal / length : normal / length;
}

}  // namespace rtu
