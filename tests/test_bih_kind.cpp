// The BIH as a registered core kind (kinds/bih/bih_kind.h): its job set-up of world-space ray
// records through a model header onto the image's grid (bih_job_setup.h, bih_model.h; the header
// fetch's timing by hand), its state cycles by hand (bih_timing.h), its settings' checks, its
// counters, and, as its fixture's checkOracle() (test_kind_oracles.cpp), the golden traversal
// behind that set-up against the float64 brute force on the grid's integers
// (bih_oracle_check.h). The equivalence tests over every kind run it through every model.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "bih_oracle_check.h"
#include "config/configuration.h"
#include "kind_fixture.h"
#include "span_records.h"

namespace rtu {
namespace {

using Kind = BihKind<>;

// A 4-bit grid (n = 4, m = 8: direction codes of scale 2^7; E = 2, C = 4), whose box is the
// vertices' [0, 15] x [0, 15] x [0, 10] world units: its longest side 15 = 2^4 - 1, so a world
// unit is a grid unit.
constexpr FixedTriangleFormat kSmallFormat{4, 8, 2, 0, 4, FixedListing::C99};

// Two triangles: 0 on the floor z = 0, (0,0,0) (15,0,0) (0,15,0); 1 at z = 10 over the far
// corner, (8,8,10) (15,8,10) (8,15,10). leafSize 4: the root is a leaf of both.
struct TwoTriangles {
  TriangleMesh mesh;
  std::vector<uint32_t> words;
  uint32_t header = 0;

  explicit TwoTriangles(const ModelPlacement& placement, uint32_t leafSize = 4) {
    mesh.vertices = {{0, 0, 0}, {15, 0, 0}, {0, 15, 0}, {8, 8, 10}, {15, 8, 10}, {8, 15, 10}};
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
    const SceneGrid grid(meshBounds(mesh), kSmallFormat);
    const ProjectedMesh projected = projectMesh(mesh, grid);
    BihBuildSettings settings;
    settings.leafSize = leafSize;
    const BihBuild tree =
        buildBih(triangleBoxes(mesh, grid, projected), sceneUpper(grid), settings);
    words = layOut(tree, projected, grid).words;
    header = appendBihModelHeader(words, grid, placement);
  }
};

RayRecord rayAt(uint32_t id, std::array<float, 3> origin, std::array<float, 3> direction,
                uint32_t model) {
  RayRecord record;
  record.id = id;
  record.origin = origin;
  record.direction = direction;
  record.modelAddress = model;
  return record;
}

BihResult traced(const std::vector<uint32_t>& words, const RayRecord& ray,
                 const BihConfig& own = {}) {
  RtuConfig config = kindConfig<Kind>();
  config.coreConfig<Kind>() = own;
  const std::vector<CoreKindResult> results =
      KindFixture<Kind>::golden(WordMemory(words), config, {HostRecord{ray}});
  return std::get<BihResult>(results.at(0));
}

}  // namespace

TEST_CASE("BIH kind: a world ray is clipped to the scene box, then put on the grid", "[bih_kind]") {
  const TwoTriangles model{ModelPlacement{}};
  const JobManagerTiming timing;
  Kind::Setup setup(WordMemory(model.words), timing, BihConfig{});
  // From (3, 4, 20) along (0, 0, -2): it enters the box at z = 10, t = 5; there its origin is
  // the grid point (3, 4, 10), its direction (0, 0, -1) the code -2^7, and a grid unit of travel
  // is half a unit of t.
  const JobSetUp<BihJob> set = setup.setUp(rayAt(7, {3, 4, 20}, {0, 0, -2}, model.header));
  CHECK(set.idWord == 7);
  CHECK_FALSE(set.job.missesBox);
  CHECK(set.job.ray.origin == GridPoint{3, 4, 10});
  CHECK(set.job.ray.omega == GridPoint{0, 0, -128});
  CHECK(set.job.ray.tClip == 5);
  CHECK(set.job.ray.worldPerGridUnit == 0.5);
  CHECK(set.job.scene.upper == GridPoint{15, 15, 10});
  CHECK(set.job.scene.format.n == 4);
  // Beside the box: no grid ray, a job that ends in AABB.
  CHECK(setup.setUp(rayAt(8, {20, 4, 20}, {0, 0, -1}, model.header)).job.missesBox);
}

TEST_CASE("BIH kind: a placed model is traced on its grid, its hit's distance in the world's t",
          "[bih_kind]") {
  ModelPlacement placement;
  placement.translation = {100, 0, 0};
  const TwoTriangles model(placement);
  // From (103, 4, 20) along (0, 0, -2): the floor (triangle 0) at grid t 10 from z = 10, world
  // t 5 + 10/2 = 10; triangle 1 lies beside the ray.
  const BihResult hit = traced(model.words, rayAt(5, {103, 4, 20}, {0, 0, -2}, model.header));
  CHECK(hit.idWord == 5);
  CHECK(hit.hit);
  CHECK(hit.primitive == 0);
  CHECK(hit.t == 10);
  CHECK(hit.distance == 10);
  CHECK(Kind::hitDistance(hit, BihConfig{}) == 10);
  // Beside the box: a miss after AABB's one cycle.
  const BihResult miss = traced(model.words, rayAt(6, {90, 4, 20}, {0, 0, -1}, model.header));
  CHECK_FALSE(miss.hit);
  CHECK(miss.cost == 1);
  CHECK(miss.distance == 0);
}

TEST_CASE("BIH kind: the first ray against a model fetches both headers", "[bih_kind]") {
  const TwoTriangles model{ModelPlacement{}};
  JobManagerTiming timing;  // 6 stages, 6 ray stages, 16 cycles a header
  Kind::Setup setup(WordMemory(model.words), timing, BihConfig{});
  const RayRecord ray = rayAt(1, {3, 4, 20}, {0, 0, -1}, model.header);
  const JobSetUp<BihJob> first = setup.setUp(ray);
  CHECK(first.headerFetch == 32);
  CHECK(first.latency == 6 + 6 + 32);
  const JobSetUp<BihJob> second = setup.setUp(ray);
  CHECK(second.headerFetch == 0);
  CHECK(second.latency == 6 + 6);
  CHECK(KindFixture<Kind>::firstDispatch(timing) == 6 + 6 + 32);
  // A model header that names no BIH image.
  std::vector<uint32_t> words = model.words;
  words[0] = 0;
  Kind::Setup broken(WordMemory(words), timing, BihConfig{});
  CHECK_THROWS_WITH(broken.setUp(ray), Catch::Contains("is not a BIH image"));
}

TEST_CASE("BIH kind: a leaf's tests issue an interval apart, the ray ends a latency after the "
          "last",
          "[bih_kind]") {
  const TwoTriangles model{ModelPlacement{}};
  const RayRecord ray = rayAt(1, {3, 4, 20}, {0, 0, -1}, model.header);
  // AABB, NODE (the root, a leaf of 2), then per triangle LEAF, TRI0, TRI1, TRI2, TEST: ten
  // states of one cycle; the first TEST takes the interval, the last the latency after its issue.
  BihConfig seed;  // 41 cycles, one test a cycle
  const BihResult a = traced(model.words, ray, seed);
  CHECK(a.cost == 10 + 1 + 41);
  CHECK(a.counts.triangleTests == 2);
  CHECK(a.counts.nodes == 1);
  CHECK(a.counts.accesses == 1 + 2 * 4);  // NODE, then LEAF and TRI0-2 per triangle
  BihConfig slow;
  slow.cycles = BihCycles{7, 2};
  CHECK(traced(model.words, ray, slow).cost == 10 + 2 + 7);
  BihConfig states;
  states.cycles = BihCycles{1, 1};
  CHECK(traced(model.words, ray, states).cost == 12);  // the golden count of states
  BihCounters counters;
  Kind::countResult(a, counters);
  CHECK(counters.bihTriangleTests == 2);
  CHECK(counters.bihBytesFetched == 9 * 16);
}

TEST_CASE("BIH kind: a leaf's last test does not wait, only the ray's last state does",
          "[bih_kind]") {
  // Leaves of one triangle: the root splits x at 7.5; triangle 0 (x 0-15) left, clip0 = 15;
  // triangle 1 (x 8-15) right, clip1 = 8.
  const TwoTriangles model(ModelPlacement{}, 1);
  // From (9, 5, 20) straight down at x = 9 (inside both children's x intervals, dist0 and dist1
  // far beyond the box): both children are entered, the near one (left, idir_x >= 0) first:
  // AABB, NODE (root), INNER, PUSH, NODE (left leaf), LEAF, TRI0-2, TEST (a hit at grid t 10:
  // the floor; not the last state, the stack holds the right child), POP, NODE (right leaf),
  // LEAF, TRI0-2, TEST (misses: (9, 5) is outside triangle 1, y < 8), the last state.
  const RayRecord ray = rayAt(1, {9, 5, 20}, {0, 0, -1}, model.header);
  BihConfig seed;
  const BihResult result = traced(model.words, ray, seed);
  CHECK(result.hit);
  CHECK(result.primitive == 0);
  CHECK(result.counts.triangleTests == 2);
  CHECK(result.counts.pushes == 1);
  // 15 states of one cycle, the first TEST 1 (the interval: the traversal goes on to POP without
  // its result, where the BVH core would wait the latency), the last TEST 41 (the latency).
  CHECK(result.cost == 15 + 1 + 41);
}

TEST_CASE("BIH kind: settings refused by name", "[bih_kind]") {
  BihConfig config;
  CHECK_NOTHROW(config.validate());
  config.cycles.triangleInterval = 42;
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("bih.triangle.interval"));
  config.cycles = BihCycles{0, 1};
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("bih.triangle.latency"));
  config.cycles = BihCycles{};
  config.format.n = 31;
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("accel.bih_format"));
  CHECK(bihFormatName(kVhdlFormat) == "vhdl");
  CHECK(parseBihFormat("c99").n == 29);
  CHECK_THROWS_AS(parseBihFormat("float"), std::invalid_argument);
}

TEST_CASE("BIH kind: its settings reach its Config, and have no effect with another core",
          "[bih_kind][config]") {
  Configuration c;
  c.set("core", "bih", ConfigSource::CommandLine);
  c.set("bih.triangle.latency", "9", ConfigSource::CommandLine);
  c.set("bih.triangle.interval", "3", ConfigSource::CommandLine);
  c.set("bih.early_out", "true", ConfigSource::CommandLine);
  c.set("accel.bih_format", "vhdl", ConfigSource::CommandLine);
  const BihConfig& own = c.values().rtu.coreConfig<Kind>();
  CHECK(own.cycles.triangleLatency == 9);
  CHECK(own.cycles.triangleInterval == 3);
  CHECK(own.earlyOut);
  CHECK(own.format.n == 30);
  CHECK(own.format.listing == FixedListing::Vhdl);
  const unsigned uses = kUseModel | kUseArithmetic;
  const Setting& latency = findSetting("bih.triangle.latency");
  CHECK(whyIneffective(latency, c.values(), uses, "render").empty());
  CHECK_THROWS_WITH(c.set("bih.triangle.latency", "0", ConfigSource::CommandLine),
                    Catch::Contains("bih.triangle.latency"));
  Configuration other;
  other.set("core", "bvh", ConfigSource::CommandLine);
  CHECK_THAT(whyIneffective(latency, other.values(), uses, "render"),
             Catch::Contains("the core kind is bvh"));
  CHECK_THAT(whyIneffective(findSetting("bih.early_out"), other.values(), uses, "render"),
             Catch::Contains("the core kind is bvh"));
}

void KindFixture<BihKind<>>::checkOracle() {
  // The frame's rays, and the same rays moved into the model taking the nearest hit ahead (the
  // clip then keeps their origins).
  for (const std::string& scene : scenes()) {
    const Frame f = frame(scene, 6, 64, 48);
    for (bool moved : {false, true}) {
      const std::vector<HostRecord> jobs = moved ? movedIntoModel(f.jobs, RaySpan::Ahead) : f.jobs;
      const RtuConfig config = kindConfig<Kind>();
      const std::vector<CoreKindResult> golden = KindFixture::golden(f.memory(), config, jobs);
      Kind::Setup setup(f.memory(), config.jobManager, BihConfig{});
      const FixedOracleCheck oracle(f.mesh, format(scene));
      Agreement agreement;
      for (size_t i = 0; i < jobs.size(); ++i) {
        const BihJob job = setup.setUp(std::get<RayRecord>(jobs[i])).job;
        const BihResult& result = std::get<BihResult>(golden[i]);
        if (job.missesBox) {
          CHECK_FALSE(result.hit);
          continue;
        }
        const std::optional<KernelHit> hit =
            result.hit ? std::optional<KernelHit>(KernelHit{result.t, result.primitive})
                       : std::nullopt;
        oracle.classifyRay(job.ray, hit, agreement);
      }
      INFO(scene << (moved ? ", moved in, ahead" : "") << ": rays " << agreement.rays << ", same "
                 << agreement.same << ", ties " << agreement.ties << ", explained "
                 << agreement.explained << ", clamped " << agreement.clamped << ", unexplained "
                 << agreement.unexplained);
      // Measured (64 x 48 rays, detail 6): sphere 847 rays reach the box, 718 the same, 129
      // explained; menger (vhdl) 1,503, 1,160 and 343; terrain 839, 538 and 301. Voxel faces
      // meet at shared edges and coplanar squares, where either of two triangles is within the
      // error.
      CHECK(agreement.unexplained == 0);
      CHECK(agreement.same > agreement.rays / 2);
      CHECK(agreement.rays > 500);
    }
  }
}

}  // namespace rtu
