// The BVH as a registered core kind (kinds/bvh/bvh_kind.h): its job set-up of world-space ray
// records through a model header (bvh_job_setup.h, with the header fetch's timing by hand), its
// settings' checks, its counters, and, as its fixture's checkOracle() (test_kind_oracles.cpp), the
// golden traversal behind that set-up against the float64 brute force of
// geometry/triangle_oracle.h on the fixture's scenes. Its hand-counted state cycles are in
// test_bvh_traversal.cpp; the equivalence tests over every kind run it through every model.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bvh_meshes.h"
#include "geometry/ray_sets.h"
#include "geometry/triangle_oracle.h"
#include "kind_fixture.h"
#include "span_records.h"
#include "triangle_margins.h"

namespace rtu {
namespace {

using Kind = BvhKind<>;

// One triangle, (-1/2, 0, 0), (1/2, 0, 0), (-1/2, 1, 0), built into an image with a model header
// placing it at `placement`.
struct OneTriangle {
  std::vector<uint32_t> words;
  uint32_t header = 0;
  explicit OneTriangle(const ModelPlacement& placement) {
    const TriangleMesh mesh = rowOfTriangles(1);
    words = layOut(buildSah(mesh).tree, mesh).words;
    header = appendBvhModelHeader(words, placement);
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

BvhResult traced(const std::vector<uint32_t>& words, const RayRecord& ray) {
  const std::vector<CoreKindResult> results =
      KindFixture<Kind>::golden(WordMemory(words), kindConfig<Kind>(), {HostRecord{ray}});
  return std::get<BvhResult>(results.at(0));
}

}  // namespace

TEST_CASE("BVH kind: a placed model is traced in its own space, t in the world's units",
          "[bvh_kind]") {
  // Moved by (4, 0, 0) and scaled by 2: the world triangle is (3, 0, 0), (5, 0, 0), (3, 2, 0).
  ModelPlacement placement;
  placement.translation = {4, 0, 0};
  placement.scale = glm::dvec3(2);
  const OneTriangle model(placement);
  // From (3.5, 0.5, 3) straight down: model point (-0.25, 0.25) at t = 3, u = v = 0.25.
  const BvhResult hit = traced(model.words, rayAt(5, {3.5f, 0.5f, 3}, {0, 0, -1}, model.header));
  CHECK(hit.idWord == 5);
  CHECK(hit.hit);
  CHECK(hit.primitive == 0);
  CHECK(hit.t == Approx(3).epsilon(1e-6));
  CHECK(hit.u == Approx(0.25).epsilon(1e-6));
  CHECK(hit.v == Approx(0.25).epsilon(1e-6));
  // (4.9, 1.5): model (0.45, 0.75), beyond the hypotenuse.
  CHECK_FALSE(traced(model.words, rayAt(6, {4.9f, 1.5f, 3}, {0, 0, -1}, model.header)).hit);
}

TEST_CASE("BVH kind: the first ray against a model fetches both headers", "[bvh_kind]") {
  const OneTriangle model{ModelPlacement{}};
  JobManagerTiming timing;  // 6 stages, 6 ray stages, 16 cycles a header
  Kind::Setup setup(WordMemory(model.words), timing, BvhConfig{});
  const RayRecord ray = rayAt(1, {0, 0.25f, 1}, {0, 0, -1}, model.header);
  const JobSetUp<BvhJob> first = setup.setUp(ray);
  CHECK(first.headerFetch == 32);  // the model header and the image's, 16 words each
  CHECK(first.latency == 6 + 6 + 32);
  CHECK(first.job.image.nodes == 16);  // the image at word 0, its nodes after its header
  const JobSetUp<BvhJob> second = setup.setUp(ray);
  CHECK(second.headerFetch == 0);
  CHECK(second.latency == 12);
}

TEST_CASE("BVH kind: a model header naming no BVH image is refused", "[bvh_kind]") {
  OneTriangle model{ModelPlacement{}};
  std::vector<uint32_t> words = model.words;
  words[model.header + 15] = 2;  // not on a multiple of 4 words
  Kind::Setup misaligned(WordMemory(words), JobManagerTiming{}, BvhConfig{});
  CHECK_THROWS_WITH(misaligned.setUp(rayAt(0, {0, 0, 1}, {0, 0, -1}, model.header)),
                    Catch::Contains("not on a multiple of 4 words"));
  words[model.header + 15] = 16;  // the nodes, not a header
  Kind::Setup notBvh(WordMemory(words), JobManagerTiming{}, BvhConfig{});
  CHECK_THROWS_WITH(notBvh.setUp(rayAt(0, {0, 0, 1}, {0, 0, -1}, model.header)),
                    Catch::Contains("is not a BVH image"));
  CHECK_THROWS_WITH(checkCoreTakes("bvh", {HostRecord{TValueRecord{}}}),
                    Catch::Contains("the bvh core takes no"));
}

TEST_CASE("BVH kind: settings are checked by name", "[bvh_kind]") {
  BvhConfig config;
  CHECK_NOTHROW(config.validate());
  config.stackDepth = 0;
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("core.stack_depth"));
  config = BvhConfig{};
  config.cycles.boxLatency = 0;
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("core.box.latency"));
  config = BvhConfig{};
  config.cycles = BvhCycles{1, 4, 5};
  CHECK_THROWS_WITH(config.validate(), Catch::Contains("core.triangle.interval (5) exceeds"));
  // Checked in every RTU configuration, whichever kind it chooses, as the SVO's are.
  RtuConfig rtu;
  rtu.coreConfig<Kind>().stackDepth = 0;
  CHECK_THROWS_WITH(validate(rtu), Catch::Contains("core.stack_depth"));
  CHECK(kindConfig<Kind>().outputLink().recordBytes == 32);
  CHECK(parseTriangleTest("moller-trumbore") == TriangleTest::MollerTrumbore);
  CHECK(toString(TriangleTest::Watertight) == "watertight");
  CHECK_THROWS_AS(parseTriangleTest("badouel"), std::invalid_argument);
}

TEST_CASE("BVH kind: counters of one ray", "[bvh_kind]") {
  // The one triangle from above: root leaf. ROOT0, ROOT1, ROOT_TEST, REF, TRI0-2, TEST, POP: six
  // accesses of 16 bytes, one node, one box test, one triangle test.
  const OneTriangle model{ModelPlacement{}};
  const BvhResult result = traced(model.words, rayAt(0, {0, 0.25f, 1}, {0, 0, -1}, model.header));
  REQUIRE(result.hit);
  CHECK(result.cost == 9);
  BvhCounters counters;
  Kind::countResult(result, counters);
  CHECK(counters.bvhNodesVisited == 1);
  CHECK(counters.bvhBoxTests == 1);
  CHECK(counters.bvhTriangleTests == 1);
  CHECK(counters.bvhStackOverflows == 0);
  CHECK(counters.bvhBytesFetched == 6 * 16);
}

// The golden traversal against the oracle on the fixture's scenes (identity placement: the ray
// records are the model-space rays, exactly). Agreement as test_bvh_oracle.cpp's: the same
// triangle or both missing, or hits within 4 float32 ulp in t (voxel faces share edges and
// planes), or a ray passing within 4 float32 ulp of a disputed triangle's edge.
void KindFixture<BvhKind<>>::checkOracle() {
  // The frame's rays, and the same rays moved into the model with a span: the oracle's closest
  // hit then from the span's t_min on.
  for (const std::string& scene : scenes()) {
    const Frame f = frame(scene, 6, 64, 48);
    for (RaySpan span : {RaySpan::Line, RaySpan::Ahead}) {
      const std::vector<HostRecord> jobs = span == RaySpan::Line ? f.jobs
                                                                 : movedIntoModel(f.jobs, span);
      const double tMin = span == RaySpan::Line ? 0.0 : kBvhSpanTMin;
      const std::vector<CoreKindResult> golden =
          KindFixture::golden(f.memory(), kindConfig<Kind>(), jobs);
      const Aabb<double> box = meshBounds(f.mesh);
      const double scale = std::max(largestCoordinate(box.lower), largestCoordinate(box.upper));
      int same = 0, ties = 0, explained = 0, unexplained = 0;
      for (size_t i = 0; i < jobs.size(); ++i) {
        const RayRecord& record = std::get<RayRecord>(jobs[i]);
        const Ray ray{glm::dvec3(record.origin[0], record.origin[1], record.origin[2]),
                      glm::dvec3(record.direction[0], record.direction[1], record.direction[2])};
        const std::optional<OracleHit> oracle = closestHit(f.mesh, ray, tMin, INFINITY);
        const BvhResult& result = std::get<BvhResult>(golden[i]);
        if (result.hit == oracle.has_value() && (!oracle || result.primitive == oracle->triangle)) {
          ++same;
        } else if (result.hit && oracle &&
                   std::abs(result.t - oracle->t) <= 4 * 0x1.0p-23 * std::abs(oracle->t)) {
          ++ties;
        } else {
          double margin = INFINITY;
          if (result.hit) margin = edgeMargin(f.mesh, result.primitive, ray);
          if (oracle) margin = std::min(margin, edgeMargin(f.mesh, oracle->triangle, ray));
          const double within = 4 * 0x1.0p-23 * std::max(scale, largestCoordinate(ray.origin));
          ++(margin <= within ? explained : unexplained);
        }
      }
      INFO(scene << (span == RaySpan::Line ? "" : ", moved in, ahead") << ": " << same << " same, "
                 << ties << " ties, " << explained << " explained");
      CHECK(unexplained == 0);
      CHECK(same > static_cast<int>(jobs.size()) * 9 / 10);
    }
  }
}

}  // namespace rtu
