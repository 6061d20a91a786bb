#pragma once
// The SVO kind's test fixture (tests/kind_fixture.h): the procedural scenes, frames of primary
// rays of the default camera as t-value records, the golden model, and the voxel walk as its
// oracle.

#include <algorithm>
#include <string>
#include <vector>

#include "inputs/camera.h"
#include "kinds/svo/golden_model.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"
#include "kinds/svo/svo_image.h"
#include "rtu/model_header.h"
#include "three_balls_scene.h"

namespace rtu {

template <>
struct KindFixture<SvoKind> {
  struct Frame {
    std::string scene;
    SvoBuild build;
    std::vector<TValueRecord> jobs;  // job i's id is i
    WordMemory memory() const { return build.image.memory(); }
  };

  static std::vector<std::string> scenes() { return proceduralSceneNames(); }

  // The scene built as an octree of `depth` levels.
  static Frame frame(const std::string& scene, int depth, int width, int height) {
    Frame frame{scene, buildSvo(*makeProceduralScene(scene, depth)), {}};
    frame.jobs = makeFrameJobs(fixtureCamera(width, height), frame.build.image.root);
    return frame;
  }

  // Appends a model header (the model placed as it was built) to the frame's image.
  static std::vector<HostRecord> rayRecords(Frame& frame, int width, int height) {
    const uint32_t header = appendModelHeader(frame.build.image, ModelPlacement{});
    const std::vector<RayRecord> rays = makeFrameRayRecords(fixtureCamera(width, height), header);
    return std::vector<HostRecord>(rays.begin(), rays.end());
  }

  // Three instances, 40 rays against each of the first two, the rest against the third.
  struct InstancedRays {
    ThreeBalls scene;
    std::vector<HostRecord> records;
    WordMemory memory() const { return scene.memory.memory(); }
  };
  static InstancedRays instancedRays() {
    InstancedRays rays;
    const std::vector<RayRecord> frame = frameRays(16, 10);
    for (size_t i = 0; i < frame.size(); ++i) {
      RayRecord record = frame[i];
      record.modelAddress = rays.scene.instances[std::min<size_t>(i / 40, 2)].headerAddress;
      rays.records.push_back(record);
    }
    return rays;
  }

  static std::vector<CoreKindResult> golden(const WordMemory& memory, const RtuConfig& config,
                                            const std::vector<TValueRecord>& jobs) {
    const std::vector<TraversalResult> golden =
        GoldenModel(memory, config.coreConfig<SvoKind>()).traceAll(jobs);
    return std::vector<CoreKindResult>(golden.begin(), golden.end());
  }

  // A t-value record passes the P_STAGES registers alone.
  static uint64_t firstDispatch(const JobManagerTiming& timing) {
    return static_cast<uint64_t>(timing.stages);
  }

  // Q28.12 converted exactly, and a stack shallow enough to overflow.
  static void otherArithmetic(RtuConfig& config) {
    config.coreConfig<SvoKind>().format = FixedFormat{28, 12};
    config.coreConfig<SvoKind>().conversion = FloatConversion::Exact;
    config.coreConfig<SvoKind>().stackFrames = 3;
  }

  // The voxel walk against the golden model (test_svo_voxel_walk.cpp).
  static void checkOracle();
};

}  // namespace rtu
