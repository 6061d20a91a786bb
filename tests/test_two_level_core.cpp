// The BVH core's two-level traversal (kinds/bvh/bvh_traversal.h, "Two levels") over the two-level
// memory image (kinds/bvh/two_level_image.h) against the two-level golden walk
// (kinds/bvh/two_level_traversal.h), which shares the mesh traversal but walks the top level and
// moves the ray apart from the core; and through the job set-up of world-space ray records and the
// cycle-accurate RTU. Four overlapping instances of spider.obj (test_two_level_oracle.cpp's), two
// frames of placements over the same mesh images.
#include <catch2/catch.hpp>

#include <cmath>

#include "bvh_meshes.h"
#include "geometry/ray_sets.h"
#include "kind_fixture.h"
#include "kinds/bvh/bvh_kind.h"
#include "kinds/bvh/langr_builder.h"
#include "kinds/bvh/sah_builder.h"
#include "kinds/bvh/two_level_image.h"
#include "kinds/bvh/two_level_traversal.h"
#include "kinds/core_result.h"
#include "placed_world.h"
#include "rtu/golden_shell.h"
#include "run/lt_simulation.h"
#include "run/rtu_simulation.h"

namespace rtu {
namespace {

using Kind = BvhKind<WatertightIntersector>;

std::vector<RayRecord> worldRays(const TwoLevelBvh& bvh, uint32_t modelAddress) {
  Aabb<double> world;
  for (const Aabb<double>& box : bvh.topLevel().worldBoxes) {
    world.grow(box.lower);
    world.grow(box.upper);
  }
  std::vector<Ray> rays = viewRays(world, 3, 16, 16);
  const std::vector<Ray> random = randomRays(world, 300, 5);
  rays.insert(rays.end(), random.begin(), random.end());
  std::vector<RayRecord> records;
  for (const Ray& ray : rays) {
    const glm::vec3 o(ray.origin), d(ray.direction);
    records.push_back(RayRecord{
        static_cast<uint32_t>(records.size()), {o.x, o.y, o.z}, {d.x, d.y, d.z}, modelAddress});
  }
  return records;
}

BvhRay bvhRay(const RayRecord& r) {
  return makeBvhRay(Vec3<float>(r.origin[0], r.origin[1], r.origin[2]),
                    Vec3<float>(r.direction[0], r.direction[1], r.direction[2]), 0.0f, INFINITY);
}

// The core's result equals the golden walk's: hit, t, u, v bit for bit, the triangle as its index
// in the instances concatenated, and the counts of both levels summed.
void checkSame(const BvhResult& core, const TwoLevelResult& golden, uint32_t meshTriangles) {
  REQUIRE(core.hit == golden.hit);
  CHECK(core.counts.nodes == golden.counts.top.nodes + golden.counts.mesh.nodes);
  CHECK(core.counts.boxTests == golden.counts.top.boxTests + golden.counts.mesh.boxTests);
  CHECK(core.counts.triangleTests == golden.counts.mesh.triangleTests);
  CHECK(core.counts.instances == golden.counts.top.instances);
  if (!golden.hit) return;
  CHECK(core.t == golden.t);
  CHECK(core.u == golden.u);
  CHECK(core.v == golden.v);
  CHECK(core.primitive == golden.instance * meshTriangles + golden.primitive);
}

}  // namespace

TEST_CASE("Two-level BVH core equals the two-level golden walk over two frames", "[two_level]") {
  const TriangleMesh& mesh = assimpObjModel("spider.obj");
  const Aabb<double> box = meshBounds(mesh);
  std::vector<MeshBvh> meshes;
  meshes.push_back(meshBvh(buildLangr(mesh).tree, mesh));
  TwoLevelBvh bvh(std::move(meshes));
  TwoLevelImage image(bvh);
  const auto triangles = static_cast<uint32_t>(mesh.triangles.size());
  int hits = 0, rays = 0;
  for (const double shift : {0.0, 0.3 * box.extent().x}) {
    bvh.place(overlappingInstances(box, shift));
    image.writeFrame(bvh);
    TwoLevelTraversal<WatertightIntersector> golden(bvh);
    GoldenShell<Kind> core(image.memory(), Kind::Config{});
    for (const RayRecord& record : worldRays(bvh, image.worldHeader())) {
      BvhResult result;
      core.run(record.id, image.job(bvhRay(record)), result);
      const TwoLevelResult expected = golden.trace(record, 0, INFINITY);
      checkSame(result, expected, triangles);
      hits += expected.hit;
      ++rays;
    }
  }
  CHECK(hits > 100);  // measured 166 of 2,136: random rays in the world box miss mostly
}

TEST_CASE("Two-level BVH core: ray records through the job set-up and the cycle-accurate RTU",
          "[two_level]") {
  const TriangleMesh& mesh = assimpObjModel("spider.obj");
  std::vector<MeshBvh> meshes;
  meshes.push_back(meshBvh(buildLangr(mesh).tree, mesh));
  TwoLevelBvh bvh(std::move(meshes));
  bvh.place(overlappingInstances(meshBounds(mesh), 0));
  TwoLevelImage image(bvh);
  image.writeFrame(bvh);
  const std::vector<RayRecord> rays = worldRays(bvh, image.worldHeader());
  RtuConfig config;
  config.core = Kind::kName;
  config.cores = 4;
  config.coreConfig<BvhKind<>>().triangleTest = TriangleTest::Watertight;
  config.coreConfig<BvhKind<>>().cycles = BvhCycles{2, 5, 1, 3};
  const std::vector<HostRecord> records(rays.begin(), rays.end());
  const std::vector<BvhResult> simulated =
      resultsOfKind<BvhKind<>>(resultsInJobOrder(simulateRtu(image.memory(), records, config)));
  REQUIRE(simulated.size() == rays.size());
  BvhKind<>::Setup setup(image.memory(), JobManagerTiming{}, config.coreConfig<BvhKind<>>());
  GoldenShell<BvhKind<>> core(image.memory(), config.coreConfig<BvhKind<>>());
  TwoLevelTraversal<WatertightIntersector> golden(bvh);
  int transformStates = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const JobSetUp<BvhJob> set = setup.setUp(rays[i]);
    CHECK(set.job.instances != 0);
    BvhResult result;
    core.run(set.idWord, set.job, result);
    CHECK(simulated[i] == result);
    checkSame(result, golden.trace(rays[i], 0, INFINITY),
              static_cast<uint32_t>(mesh.triangles.size()));
    transformStates += result.counts.instances;
  }
  CHECK(transformStates > 0);
}

TEST_CASE("Two-level BVH core: an instance's states and cycles by hand", "[two_level]") {
  // One instance of a one-triangle mesh, moved 5 along z; the ray along z from the origin hits it
  // at t = 5. Box latency 2, triangle latency 5, transform latency 3. Top level (a root leaf):
  // ROOT0, ROOT1 (2), ROOT_TEST (2), REF (1), INST0-4 (5), XFORM (3); the mesh (a root leaf):
  // ROOT0, ROOT1 (2), ROOT_TEST (2), REF, TRI0-2 (4), TEST (the leaf's last: 5), POP (the mesh's
  // entries used up: back to the top level, whose leaf is done, 1), POP (empty: OUT, 1). 28.
  TriangleMesh mesh;
  mesh.vertices = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  std::vector<MeshBvh> meshes;
  meshes.push_back(meshBvh(buildSah(mesh).tree, mesh));
  TwoLevelBvh bvh(std::move(meshes));
  bvh.place({BvhInstance{0, ModelPlacement{glm::dvec3(0, 0, 5), glm::dmat3(1.0), glm::dvec3(1)}}});
  TwoLevelImage image(bvh);
  image.writeFrame(bvh);
  BvhConfig config;
  config.cycles = BvhCycles{2, 5, 1, 3};
  GoldenShell<Kind> core(image.memory(), config);
  const RayRecord record{0, {0, 0, 0}, {0, 0, 1}, image.worldHeader()};
  BvhResult result;
  core.run(0, image.job(bvhRay(record)), result);
  CHECK(result.hit);
  CHECK(result.t == 5.0f);
  CHECK(result.primitive == 0);
  CHECK(result.counts.instances == 1);
  CHECK(result.counts.nodes == 2);
  CHECK(result.counts.accesses == 2 + 1 + 5 + 2 + 1 + 3);
  CHECK(result.cost == 28u);
}

namespace {

// Two instances on the z axis: at z = 5 a mesh of two triangles in the planes z = -0.5 and 0.5
// (a leaf each) whose boxes the axis crosses but whose triangles it misses (x + y <= -0.5), at
// z = 10 the one-triangle mesh above, which the axis hits at t = 10. The top level: a root and a
// leaf per instance.
TwoLevelBvh stackedInstances() {
  TriangleMesh missed;
  missed.vertices = {{-1, -1, -0.5}, {0.5, -1, -0.5}, {-1, 0.5, -0.5},
                     {-1, -1, 0.5},  {0.5, -1, 0.5},  {-1, 0.5, 0.5}};
  missed.triangles = {{0, 1, 2}, {3, 4, 5}};
  TriangleMesh hit;
  hit.vertices = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
  hit.triangles = {{0, 1, 2}};
  SahBuilderConfig leafEach;
  leafEach.maxLeafSize = 1;
  std::vector<MeshBvh> meshes;
  meshes.push_back(meshBvh(buildSah(missed, leafEach).tree, missed));
  meshes.push_back(meshBvh(buildSah(hit).tree, hit));
  TwoLevelBvh bvh(std::move(meshes));
  const auto along = [](uint32_t mesh, double z) {
    return BvhInstance{mesh, ModelPlacement{glm::dvec3(0, 0, z), glm::dmat3(1.0), glm::dvec3(1)}};
  };
  bvh.place({along(0, 5), along(1, 10)});
  return bvh;
}

}  // namespace

TEST_CASE("Two-level BVH core: the shared stack overflowing across levels\\, by hand",
          "[two_level]") {
  // The ray along z from the origin. Top level: ROOT0, ROOT1, ROOT_TEST, LEFT0 .. RIGHT1, DECIDE
  // (both instances hit: the one at z = 5 first, the other pushed): 8; REF, INST0-4, XFORM: 15.
  // The first mesh: ROOT0, ROOT1, ROOT_TEST, LEFT0 .. RIGHT1, DECIDE (both leaves hit: the
  // nearer entered, the other pushed): 23; REF, TRI0-2, TEST (a miss): 28; POP (the pushed leaf):
  // 29; REF, TRI0-2, TEST (a miss): 34; POP (the mesh's entries used up: back to the top level,
  // whose leaf is done): 35.
  // Stack depth 2: POP (the pushed instance): 36; REF, INST0-4, XFORM: 43; the second mesh (a
  // root leaf): ROOT0, ROOT1, ROOT_TEST, REF, TRI0-2, TEST (the hit at t = 10): 51; POP (back to
  // the top level), POP (empty: OUT): 53. Its triangle: the first mesh's 2, then its 0.
  // Stack depth 1: the mesh's push onto the full stack drops the oldest entry, the top level's
  // instance, so after 35 the POP finds the stack empty: OUT, cost 36, no hit (docs/triangles.md,
  // "The two-level BVH in the core"). The two-level golden walk (two_level_traversal.h), whose
  // top level and meshes keep stacks of their own, drops nothing and hits.
  const TwoLevelBvh bvh = stackedInstances();
  TwoLevelImage image(bvh);
  image.writeFrame(bvh);
  const RayRecord record{0, {0, 0, 0}, {0, 0, 1}, image.worldHeader()};
  for (const int depth : {2, 1}) {
    INFO("stack depth " << depth);
    BvhConfig config;
    config.stackDepth = depth;
    const TwoLevelResult walk =
        TwoLevelTraversal<WatertightIntersector>(bvh, config).trace(record, 0, INFINITY);
    CHECK(walk.hit);
    CHECK(walk.t == 10.0f);
    GoldenShell<Kind> core(image.memory(), config);
    BvhResult result;
    core.run(0, image.job(bvhRay(record)), result);
    CHECK(result.counts.dropped == (depth == 1 ? 1u : 0u));
    CHECK(result.counts.instances == (depth == 1 ? 1u : 2u));
    CHECK(result.counts.triangleTests == (depth == 1 ? 2u : 3u));
    CHECK(result.cost == (depth == 1 ? 36u : 53u));
    CHECK(result.hit == (depth == 2));
    if (depth == 2) {
      CHECK(result.t == 10.0f);
      CHECK(result.primitive == 2);
    }

    // Through the job set-up and the cycle-accurate RTU: the golden model's result, the
    // overflow counted.
    RtuConfig rtu;
    rtu.core = Kind::kName;
    rtu.cores = 1;
    rtu.coreConfig<BvhKind<>>().stackDepth = depth;
    const RtuRun run = simulateRtu(image.memory(), {HostRecord(record)}, rtu);
    REQUIRE(run.results.size() == 1);
    CHECK(std::get<BvhResult>(run.results[0]) == result);
    CHECK(run.statistics.allCores().bvhStackOverflows == (depth == 1 ? 1u : 0u));
    CHECK(run.statistics.allCores().bvhInstances == result.counts.instances);
  }
}

TEST_CASE("Two-level BVH core: a shallow stack on the fixture's instances in every model",
          "[two_level]") {
  // The BVH fixture's two-level frame (tests/kinds/bvh_fixture.h) with a stack of 2 entries,
  // which the top level's and the meshes' pushes share: rays overflow; the cycle-accurate RTU
  // (ideal and cached) and the loosely-timed one return the golden model's results, the
  // per-cycle reference's every cycle with ideal memory, and the run counts the overflows.
  using Fixture = KindFixture<BvhKind<>>;
  const Fixture::Frame frame = Fixture::frame("instances", 6, 24, 16);
  RtuConfig config = kindConfig<BvhKind<>>();
  config.cores = 4;
  config.coreConfig<BvhKind<>>().stackDepth = 2;
  const std::vector<CoreKindResult> golden = Fixture::golden(frame.memory(), config, frame.jobs);
  uint64_t overflowed = 0, entered = 0;
  for (const CoreKindResult& result : golden) {
    overflowed += std::get<BvhResult>(result).counts.dropped > 0;
    entered += std::get<BvhResult>(result).counts.instances;
  }
  uint64_t hits = 0;
  for (const CoreKindResult& result : golden) hits += std::get<BvhResult>(result).hit;
  CHECK(hits > 50);        // measured 74 of 384
  CHECK(entered > 100);    // measured 153
  CHECK(overflowed > 20);  // measured 39
  const RtuRun ideal = simulateRtu(frame.memory(), frame.jobs, config);
  CHECK(resultsInJobOrder(ideal) == golden);
  checkEqualsRtl(ideal, runRtlTop(frame.memory(), frame.jobs, rtlTopConfig(config)));
  CHECK(ideal.statistics.allCores().bvhStackOverflows == overflowed);
  CHECK(ideal.statistics.allCores().bvhInstances == entered);
  config.memory.ideal = false;
  CHECK(resultsInJobOrder(simulateRtu(frame.memory(), frame.jobs, config)) == golden);
  CHECK(resultsInJobOrder(runLooselyTimed(frame.memory(), frame.jobs, config)) == golden);
}

}  // namespace rtu
