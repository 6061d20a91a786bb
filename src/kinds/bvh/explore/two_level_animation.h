#pragma once
// An animated scene file (docs/scenes.md) on the BVH core as seed 003's two-level object BVH
// (S3 §3.2.1; issue 27 §2, issue 28 §2: `rtusim animate --core bvh`): each model's mesh BVH built
// once by the configured builder (accel.builder) and kept in memory; per frame the instances'
// placements at the frame's time, the top level rebuilt over their world boxes (two_level.h, its
// wall-clock build time taken as seed 003 takes its build times: the build alone, from the
// instances' boxes to the laid-out top level), the top level and instance records rewritten after
// the meshes (two_level_image.h), and the frame's primary rays (world-space ray records against
// the world header) run on the chosen model (run/model_run.h): golden (its costs in the RTU
// recurrence, memory ideal), lt or ca. The core walks both levels itself (bvh_traversal.h,
// "Two levels"). No hit buffer and no scene manager: every pixel's ray is one job.

#include <cstdint>
#include <functional>
#include <vector>

#include "base/statistics.h"
#include "config/run_config.h"
#include "geometry/triangle_mesh.h"
#include "inputs/camera.h"
#include "kinds/bvh/bvh_kind.h"
#include "kinds/bvh/two_level.h"
#include "kinds/bvh/two_level_image.h"
#include "run/model_run.h"
#include "scene/scene_file.h"

namespace rtu {

// A frame of the two-level BVH's animation, declared in the order of animate's CSV columns.
struct TwoLevelFrameStatistics {
  int frame = 0;
  double time = 0.0;  // seconds into the animation
  uint64_t pixels = 0;
  uint64_t hits = 0;
  uint64_t instances = 0;        // placed in the frame
  double topBuildSeconds = 0.0;  // the top level's build, wall clock
  uint64_t topNodes = 0;
  double topSah = 0.0;      // unit costs, over the instances' world boxes (accel_quality.h)
  double topSahSeed = 0.0;  // seed 003's costs (box 1, triangle 2)
  // The run's counters (bvh_counters.h: bvh_instances, bvh_nodes_visited, bvh_triangle_tests;
  // the cores' busy cycles).
  uint64_t instancesEntered = 0;  // XFORM states of every ray
  uint64_t nodesVisited = 0;      // both levels
  uint64_t triangleTests = 0;
  uint64_t traversalCycles = 0;  // the rays' costs summed
  uint64_t cycles = 0;           // the frame on the RTU (recurrence, lt or ca)
  double hostSeconds = 0.0;
  double clockMhz = 100.0;

  double instancesPerRay() const { return pixels ? double(instancesEntered) / pixels : 0.0; }
  double frameMs() const { return cycles / (clockMhz * 1e3); }
  double framesPerSecond() const { return cycles ? clockMhz * 1e6 / cycles : 0.0; }

  static const StatisticGroup<TwoLevelFrameStatistics>& declaration();
};

struct TwoLevelFrame {
  Camera camera;
  std::vector<BvhInstance> instances;  // placed at the frame's time
  std::vector<BvhResult> results;  // x + y * width; primitive: its index in the instances' order
  TwoLevelFrameStatistics statistics;
};

// What a frame rewrites: the two-level BVH (its top level; copies share the meshes' BVHs) and the
// memory image (the top level, instance records and world header after the meshes' images). Each
// thread rendering frames owns one, a copy of the animation's, the image's copy of the meshes'
// images included.
struct TwoLevelWorkspace {
  TwoLevelBvh bvh;
  TwoLevelImage image;
};

struct TwoLevelAnimationOptions {
  AccelSpec accel;     // the meshes' builder
  TopLevelConfig top;  // the top level's builder and leaf size
  ModelKind model = ModelKind::Golden;
  RtuConfig rtu;  // its core must be bvh
};

class TwoLevelAnimation {
 public:
  // Loads and builds every model's mesh (throws what loading and building throw, naming the
  // model; std::invalid_argument for a core other than bvh).
  TwoLevelAnimation(const SceneDescription& scene, TwoLevelAnimationOptions options);

  TwoLevelFrame render(int frame);
  // Every frame in order, `threads` at a time on copies of the structure (animate --threads),
  // each handed to `take` in frame order: the results and counts are those of render() frame by
  // frame, whatever `threads` (the wall-clock times aside). More than one thread needs the golden
  // model, whose runs share nothing: std::invalid_argument otherwise (a cycle-accurate or
  // loosely-timed frame is a SystemC simulation, one at a time in a process).
  void renderFrames(int threads, const std::function<void(const TwoLevelFrame&)>& take);

  // The instance a result's primitive lies in, and its triangle's unit normal in the world of
  // `frame`, facing pixel (x, y)'s ray (for shading).
  size_t instanceOf(uint32_t primitive) const;
  glm::dvec3 worldNormal(const TwoLevelFrame& frame, int x, int y, const BvhResult& hit) const;

  const std::vector<double>& meshBuildSeconds() const { return meshSeconds_; }
  const std::vector<TriangleMesh>& meshes() const { return meshes_; }
  // The memory image's words (the meshes', then a frame's top level, records and header).
  uint64_t imageWords() const { return workspace_.image.words().size(); }

 private:
  std::vector<BvhInstance> placements(double time) const;
  TwoLevelFrame render(int frame, TwoLevelWorkspace& workspace) const;

  const SceneDescription& scene_;
  TwoLevelAnimationOptions options_;
  std::vector<TriangleMesh> meshes_;
  std::vector<double> meshSeconds_;
  TwoLevelWorkspace workspace_;
  std::vector<uint32_t> primitiveBases_;  // per instance
};

}  // namespace rtu
