#pragma once
// The BVH kind's test fixture (tests/kind_fixture.h): procedural scenes' voxel faces (in the SVO
// cube [-1,1]^3, so the default camera frames them as it frames the octrees) built by three of
// the builders, frames of primary rays of the default camera as world-space ray records against a
// model header, the golden traversal behind the kind's job set-up, and the float64 brute force of
// geometry/triangle_oracle.h as its oracle (test_bvh_kind.cpp). The scene "instances" is a
// two-level BVH (kinds/bvh/two_level_image.h): four instances of two meshes, moved, turned and
// scaled, so every equivalence test walks the core's INST0-4 and XFORM states too; its mesh is
// the instances' triangles placed into the world in double and concatenated, as a two-level hit
// names them.

#include <string>
#include <vector>

#include "inputs/camera.h"
#include "kinds/bvh/bvh_kind.h"
#include "kinds/bvh/bvh_model.h"
#include "kinds/bvh/langr_builder.h"
#include "kinds/bvh/lbvh_builder.h"
#include "kinds/bvh/sah_builder.h"
#include "kinds/bvh/two_level_image.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/voxel_faces.h"
#include "placed_apart.h"
#include "placed_world.h"
#include "rtu/golden_shell.h"

namespace rtu {

template <>
struct KindFixture<BvhKind<>> {
  using Kind = BvhKind<>;

  struct Frame {
    std::string scene;
    TriangleMesh mesh;
    std::vector<uint32_t> words;   // the image at word 0, then its model header
    std::vector<HostRecord> jobs;  // ray records, job i's id is i
    WordMemory memory() const { return WordMemory(words); }
  };

  // Each built by another builder: sphere binned SAH, menger langr, terrain Morton codes; and
  // the two-level "instances".
  static std::vector<std::string> scenes() { return {"sphere", "menger", "terrain", "instances"}; }

  // The scene's voxel faces at depth `detail` - 2 (detail 6: a 16^3 grid, some thousand
  // triangles), with an identity placement; "instances": the two-level frame below.
  static Frame frame(const std::string& scene, int detail, int width, int height) {
    if (scene == "instances") return instancesFrame(detail, width, height);
    Frame frame{scene, voxelFaces(*makeProceduralScene(scene, detail - 2)), {}, {}};
    frame.words = layOut(tree(scene, frame.mesh), frame.mesh).words;
    const uint32_t header = appendBvhModelHeader(frame.words, ModelPlacement{});
    frame.jobs = cameraRecords(fixtureCamera(width, height), header);
    return frame;
  }

  // The frame's own records are ray records already.
  static std::vector<HostRecord> rayRecords(Frame& frame, int, int) { return frame.jobs; }

  // One image, three model headers placing it apart (tests/placed_apart.h).
  using InstancedRays = PlacedApart<Frame>;
  static InstancedRays instancedRays() {
    return placedApart(frame("sphere", 5, 16, 10), [](Frame& f, const ModelPlacement& placement) {
      return appendBvhModelHeader(f.words, placement);
    });
  }

  static std::vector<CoreKindResult> golden(const WordMemory& memory, const RtuConfig& config,
                                            const std::vector<HostRecord>& jobs) {
    return goldenBehindSetup<Kind>(memory, config, jobs);
  }
  static uint64_t firstDispatch(const JobManagerTiming& timing) {
    return rayRecordFirstDispatch(timing);
  }

  // Moller-Trumbore, the axis child order, a stack shallow enough to drop entries, and units of
  // several cycles.
  static void otherArithmetic(RtuConfig& config) {
    BvhConfig& own = config.coreConfig<Kind>();
    own.triangleTest = TriangleTest::MollerTrumbore;
    own.childOrder = ChildOrder::Axis;
    own.stackDepth = 2;
    own.cycles = BvhCycles{3, 7, 2};
  }

  // The oracle against the golden traversal (test_bvh_kind.cpp).
  static void checkOracle();

 private:
  static std::vector<HostRecord> cameraRecords(const Camera& camera, uint32_t header) {
    const std::vector<RayRecord> rays = makeFrameRayRecords(camera, header);
    return std::vector<HostRecord>(rays.begin(), rays.end());
  }

  // A sphere's and a Menger sponge's voxel faces at depth `detail` - 3, each built by the binned
  // builder once, placed four times (moved, turned about one axis and two, scaled uniformly and
  // not) in the cube the camera frames; their boxes overlap, so rays enter several instances.
  static Frame instancesFrame(int detail, int width, int height) {
    const std::vector<TriangleMesh> meshes = {
        voxelFaces(*makeProceduralScene("sphere", detail - 3)),
        voxelFaces(*makeProceduralScene("menger", detail - 3))};
    const auto at = [](uint32_t mesh, glm::dvec3 offset, glm::dvec3 degrees, glm::dvec3 scale) {
      return BvhInstance{mesh, ModelPlacement{offset, rotationFromEulerDegrees(degrees), scale}};
    };
    const std::vector<BvhInstance> instances = {
        at(0, {-0.45, 0.1, 0}, {0, 0, 0}, glm::dvec3(0.6)),
        at(1, {0.45, 0, 0.2}, {0, 30, 0}, glm::dvec3(0.55)),
        at(0, {0.05, -0.55, 0.3}, {0, 0, 20}, {0.9, 0.35, 0.9}),
        at(1, {0.1, 0.45, -0.3}, {20, 0, 45}, glm::dvec3(0.45))};
    std::vector<MeshBvh> built;
    for (const TriangleMesh& mesh : meshes) built.push_back(meshBvh(buildSah(mesh).tree, mesh));
    TwoLevelBvh bvh(std::move(built));
    bvh.place(instances);
    TwoLevelImage image(bvh);
    image.writeFrame(bvh);
    Frame frame{"instances", placedWorld(meshes, instances), image.words(), {}};
    frame.jobs = cameraRecords(fixtureCamera(width, height), image.worldHeader());
    return frame;
  }

  static BuildTree tree(const std::string& scene, const TriangleMesh& mesh) {
    if (scene == "menger") return buildLangr(mesh).tree;
    if (scene == "terrain") return buildLbvh(mesh).tree;
    return buildSah(mesh).tree;
  }
};

}  // namespace rtu
