#pragma once
// The BIH kind's test fixture (tests/kind_fixture.h): procedural scenes' voxel faces (in the SVO
// cube [-1,1]^3, as the BVH's fixture) quantised to seed 004's grid in the c99 formats, menger in
// the vhdl formats (so both kernels run through every model), built by the BIH builder with wide
// indices; frames of the default camera's primary rays as world-space ray records against a
// model header that maps the world onto the grid (bih_model.h); the golden traversal behind the
// kind's job set-up; and as its oracle the float64 brute force of geometry/triangle_oracle.h on
// the grid's integers, by bih_oracle_check.h's rule (test_bih_kind.cpp).

#include <string>
#include <vector>

#include "geometry/ray_sets.h"
#include "inputs/camera.h"
#include "kinds/bih/bih_builder.h"
#include "kinds/bih/bih_image.h"
#include "kinds/bih/bih_kind.h"
#include "kinds/bih/bih_model.h"
#include "kinds/bih/projected_triangle.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/voxel_faces.h"
#include "placed_apart.h"
#include "rtu/golden_shell.h"

namespace rtu {

template <>
struct KindFixture<BihKind<>> {
  using Kind = BihKind<>;

  struct Frame {
    std::string scene;
    TriangleMesh mesh;
    SceneGrid grid;
    std::vector<uint32_t> words;   // the image at word 0, then its model header
    std::vector<HostRecord> jobs;  // ray records, job i's id is i
    WordMemory memory() const { return WordMemory(words); }
  };

  static std::vector<std::string> scenes() { return {"sphere", "menger", "terrain"}; }

  static FixedTriangleFormat format(const std::string& scene) {
    return scene == "menger" ? kVhdlFormat : kC99Format;
  }

  // The scene's voxel faces at depth `detail` - 2 (detail 6: a 16^3 grid, some thousand
  // triangles), with an identity placement.
  static Frame frame(const std::string& scene, int detail, int width, int height) {
    TriangleMesh mesh = voxelFaces(*makeProceduralScene(scene, detail - 2));
    const SceneGrid grid(meshBounds(mesh), format(scene));
    std::vector<uint32_t> words = image(mesh, grid);
    Frame frame{scene, std::move(mesh), grid, std::move(words), {}};
    const uint32_t header = appendBihModelHeader(frame.words, grid, ModelPlacement{});
    const std::vector<RayRecord> rays = makeFrameRayRecords(camera(width, height), header);
    frame.jobs.assign(rays.begin(), rays.end());
    return frame;
  }

  // The frame's own records are ray records already.
  static std::vector<HostRecord> rayRecords(Frame& frame, int, int) { return frame.jobs; }

  // One image, three model headers placing it apart (tests/placed_apart.h).
  using InstancedRays = PlacedApart<Frame>;
  static InstancedRays instancedRays() {
    return placedApart(frame("sphere", 5, 16, 10), [](Frame& f, const ModelPlacement& placement) {
      return appendBihModelHeader(f.words, f.grid, placement);
    });
  }

  static std::vector<CoreKindResult> golden(const WordMemory& memory, const RtuConfig& config,
                                            const std::vector<HostRecord>& jobs) {
    return goldenBehindSetup<Kind>(memory, config, jobs);
  }
  static uint64_t firstDispatch(const JobManagerTiming& timing) {
    return rayRecordFirstDispatch(timing);
  }

  // A unit of 7 cycles taking a test every 2, and the early-out option (the vhdl formats come
  // with menger's image).
  static void otherArithmetic(RtuConfig& config) {
    BihConfig& own = config.coreConfig<Kind>();
    own.cycles = BihCycles{7, 2};
    own.earlyOut = true;
  }

  // The oracle against the golden traversal (test_bih_kind.cpp).
  static void checkOracle();

 private:
  static std::vector<uint32_t> image(const TriangleMesh& mesh, const SceneGrid& grid) {
    const ProjectedMesh projected = projectMesh(mesh, grid);
    const BihBuild tree = buildBih(triangleBoxes(mesh, grid, projected), sceneUpper(grid));
    return layOut(tree, projected, grid, BihIndexWidth::Wide).words;
  }
  static Camera camera(int width, int height) {
    Camera camera;
    camera.width = width;
    camera.height = height;
    return camera;
  }
};

}  // namespace rtu
