#pragma once
// The k-d kind's test fixture (tests/kind_fixture.h): procedural scenes' voxel faces (in the SVO
// cube [-1,1]^3, as the BVH's fixture), turned off the axes, built by seed 001's PBRT v1 SAH
// builder into the k-d core's image (as `build --accel kdtree` builds it), frames of the default
// camera's primary rays as world-space ray records against a model header, the golden traversal
// behind the kind's job set-up, and as its oracle the float64 brute force of
// geometry/triangle_oracle.h by kd_oracle_check.h's rule (test_kd_kind.cpp).

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "inputs/camera.h"
#include "kinds/kd/kd_image.h"
#include "kinds/kd/kd_kind.h"
#include "kinds/kd/pbrt_kd_builder.h"
#include "kinds/kd/trayracer_scene.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/voxel_faces.h"
#include "placed_apart.h"
#include "rtu/golden_shell.h"
#include "rtu/model_header.h"
#include "rtu/model_transform.h"

namespace rtu {

template <>
struct KindFixture<KdKind> {
  using Kind = KdKind;

  struct Frame {
    std::string scene;
    TriangleMesh mesh;
    TrayRacerScene built;          // the tree, lists and matrices in the image
    std::vector<uint32_t> words;   // the image at word 0, then its model header
    std::vector<HostRecord> jobs;  // ray records, job i's id is i
    WordMemory memory() const { return WordMemory(words); }
  };

  static std::vector<std::string> scenes() { return {"sphere", "menger", "terrain"}; }

  // The scene's voxel faces at depth `detail` - 2 (detail 6: a 16^3 grid, some thousand
  // triangles), turned off the axes and moved off the unit planes, with an identity placement:
  // the seed's build lists no triangle flat on a split plane at the split, and every axis-aligned
  // face is a candidate split; and a triangle whose plane lies at distance 1 from the origin has
  // a singular unit-triangle matrix (its N - C lies in the plane), which the voxel scenes' outer
  // faces at +-1 would all have (docs/triangles.md, "The k-d core").
  static Frame frame(const std::string& scene, int detail, int width, int height) {
    const Built& built = builtScene(scene, detail);
    Frame frame{scene, built.mesh, built.scene, layOutKd(built.scene).words, {}};
    const uint32_t header = appendModelHeader(frame.words, ModelPlacement{}, 0);
    const std::vector<RayRecord> rays = makeFrameRayRecords(fixtureCamera(width, height), header);
    frame.jobs.assign(rays.begin(), rays.end());
    return frame;
  }

  // The frame's own records are ray records already.
  static std::vector<HostRecord> rayRecords(Frame& frame, int, int) { return frame.jobs; }

  // One image, three model headers placing it apart (tests/placed_apart.h).
  using InstancedRays = PlacedApart<Frame>;
  static InstancedRays instancedRays() {
    return placedApart(frame("sphere", 5, 16, 10), [](Frame& f, const ModelPlacement& placement) {
      return appendModelHeader(f.words, placement, 0);
    });
  }

  static std::vector<CoreKindResult> golden(const WordMemory& memory, const RtuConfig& config,
                                            const std::vector<HostRecord>& jobs) {
    return goldenBehindSetup<Kind>(memory, config, jobs);
  }
  static uint64_t firstDispatch(const JobManagerTiming& timing) {
    return rayRecordFirstDispatch(timing);
  }

  // A one-entry short stack (restarts), units of several cycles, the divider toward zero and the
  // intended t_max.
  static void otherArithmetic(RtuConfig& config) {
    KdTraversalConfig& own = config.coreConfig<Kind>();
    own.stackDepth = 1;
    own.cycles = KdCycles{3, 7, 2};
    own.division = Division::TowardZero;
    own.tMaxClamp = KdTMaxClamp::Intended;
  }

  // The oracle against the golden traversal (test_kd_kind.cpp).
  static void checkOracle();

 private:
  struct Built {
    TriangleMesh mesh;
    TrayRacerScene scene;
  };
  // Each scene built once per process: the equivalence tests ask for the same frame in hundreds
  // of sections, and the PBRT build takes far longer than the BVH's.
  static const Built& builtScene(const std::string& scene, int detail) {
    static std::map<std::pair<std::string, int>, Built> cache;
    auto found = cache.find({scene, detail});
    if (found == cache.end()) {
      TriangleMesh mesh = turned(voxelFaces(*makeProceduralScene(scene, detail - 2)));
      TrayRacerScene built = build(mesh);
      found = cache.emplace(std::make_pair(scene, detail), Built{std::move(mesh), std::move(built)})
                  .first;
    }
    return found->second;
  }
  static TriangleMesh turned(TriangleMesh mesh) {
    const glm::dmat3 rotation = rotationFromEulerDegrees({20, 30, 10});
    for (glm::dvec3& v : mesh.vertices) v = 0.9 * (rotation * v) + glm::dvec3(0.05, -0.03, 0.02);
    return mesh;
  }
  // As `build --accel kdtree` builds it (explore/accel_build.cpp): R1's triangle boxes, the team's
  // parameters, one material.
  static TrayRacerScene build(const TriangleMesh& mesh) {
    std::vector<glm::dvec3> corners, normals;
    for (const auto& triangle : mesh.triangles) {
      for (uint32_t v : triangle) corners.push_back(mesh.vertices[v]);
      normals.push_back(glm::dvec3(0.0, 0.0, 1.0));
    }
    const KdBuild tree = buildPbrtKd(pbrtTriangleBoxes(corners), PbrtKdParameters{});
    return makeTrayRacerScene(tree, corners, normals, TrayRacerMaterial{});
  }
};

}  // namespace rtu
