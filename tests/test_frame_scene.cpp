// The frame scene of a run's kind (explore/frame_scene.h): what each kind's image and records are.

#include <catch2/catch.hpp>

#include <variant>

#include "explore/frame_scene.h"
#include "rtu/model_header.h"

namespace rtu {
namespace {

RunConfig smallFrame(const std::string& core) {
  RunConfig settings;
  settings.rtu.core = core;
  settings.scene.procedural = "sphere";
  settings.scene.depth = 4;
  settings.camera.width = 8;
  settings.camera.height = 6;
  return settings;
}

}  // namespace

TEST_CASE("Frame scene of the BVH: ray records naming a model header after the structure",
          "[frame_scene]") {
  const RunConfig settings = smallFrame("bvh");
  const FrameScene scene = loadFrameScene(settings);
  CHECK(scene.core == "bvh");
  CHECK(!scene.mesh.triangles.empty());
  // The header is the image's last 16 words and names the structure at word 0.
  REQUIRE(scene.entry + 16 == scene.words.size());
  CHECK(readModelHeader(scene.memory(), scene.entry).root == 0);
  const std::vector<HostRecord> records = frameRecords(scene, settings);
  REQUIRE(records.size() == 48);
  for (size_t i = 0; i < records.size(); ++i) {
    const auto* ray = std::get_if<RayRecord>(&records[i]);
    REQUIRE(ray != nullptr);
    CHECK(ray->modelAddress == scene.entry);
    CHECK(ray->id == i);
  }
}

TEST_CASE("Frame scene of the octree: t-value records from its root", "[frame_scene]") {
  const RunConfig settings = smallFrame("svo");
  const FrameScene scene = loadFrameScene(settings);
  CHECK(scene.core == "svo");
  CHECK(scene.stackNeeded == 3);  // depth 4: descriptors down to level 3
  const std::vector<HostRecord> records = frameRecords(scene, settings);
  REQUIRE(records.size() == 48);
  for (const HostRecord& record : records) {
    const auto* job = std::get_if<TValueRecord>(&record);
    REQUIRE(job != nullptr);
    CHECK(job->root == scene.entry);
  }
  // A stack too small for the tree is refused on every model, golden included (issue 33: one
  // rule), naming the scene; allowed, its overflowing rays are flagged.
  RunConfig shallow = settings;
  shallow.rtu.coreConfig<SvoKind>().stackFrames = 2;
  for (const ModelKind model : {ModelKind::CycleAccurate, ModelKind::Golden}) {
    shallow.model = model;
    CHECK_THROWS_WITH(frameRecords(scene, shallow),
                      Catch::Contains("scene 'sphere': the tree at root 0") &&
                          Catch::Contains("needs 3 stack frames; 2 are configured"));
  }
  shallow.allowStackOverflow = true;
  CHECK(frameRecords(scene, shallow).size() == 48);
}

TEST_CASE("Frame scene: another kind's settings are not its own", "[frame_scene]") {
  const FrameScene scene = loadFrameScene(smallFrame("svo"));
  CHECK_THROWS_WITH(frameRecords(scene, smallFrame("bvh")),
                    "a scene built for the svo core cannot run on the bvh core");
  CHECK(frameSceneKey(smallFrame("svo")) != frameSceneKey(smallFrame("bvh")));
  RunConfig other = smallFrame("bvh");
  other.accel.builder = "lbvh";
  CHECK(frameSceneKey(other) != frameSceneKey(smallFrame("bvh")));
}

}  // namespace rtu
