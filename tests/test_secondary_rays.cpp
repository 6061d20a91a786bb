// Secondary rays and any-hit traversal (issue 32): the span bits of ray records, the any-hit
// traversal against the nearest hit ahead and against the geometric oracle, the spawn against a
// float64 reference computed here, self-intersection, sampling and orders.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "explore/ray_passes.h"
#include "inputs/host_buffers.h"
#include "inputs/ray_order.h"
#include "inputs/ray_workload.h"
#include "kinds/core_result.h"
#include "kinds/svo/golden_model.h"
#include "kinds/svo/procedural_scenes.h"
#include "kinds/svo/svo_builder.h"
#include "kinds/svo/svo_voxel_walk.h"
#include "run/model_run.h"

using namespace rtu;

namespace {

constexpr double kStep = 0x1p-16;  // Q16.16

// A procedural scene at depth 6 with an identity model header after it (model = world).
struct Model {
  SvoImage image;
  uint32_t header = 0;
  explicit Model(const std::string& scene, int depth = 6)
      : image(buildSvo(*makeProceduralScene(scene, depth)).image),
        header(appendModelHeader(image, ModelPlacement{})) {}
};

Camera camera(int width, int height) {
  Camera c;
  c.width = width;
  c.height = height;
  return c;
}

RayWorkload workload(const Model& model, RayType type, const Camera& view = camera(40, 24)) {
  RayWorkloadSpec spec;
  spec.secondary.type = type;
  spec.secondary.lights = {Light::point({2.0, 4.0, -3.0}), Light::point({-3.0, 2.5, 1.0})};
  spec.secondary.samples = 2;
  return makeRayWorkload(model.image.memory(), model.header, view, GoldenConfig{}, spec);
}

std::vector<RayRecord> withSpan(std::vector<RayRecord> rays, RaySpan span) {
  for (RayRecord& ray : rays) ray.span = span;
  return rays;
}

glm::dvec3 vec(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }

}  // namespace

TEST_CASE("Ray records carry their span in bits 31:30 of the first word", "[secondary]") {
  std::vector<RayRecord> rays(3);
  rays[0].id = 5;
  rays[1].id = 6;
  rays[1].span = RaySpan::Ahead;
  rays[2].id = kMaxRayId;
  rays[2].span = RaySpan::AnyHit;
  std::vector<uint32_t> words = encodeRayRecords(rays);
  CHECK(words[0] == 5);
  CHECK(words[8] == (6u | 1u << 30));
  CHECK(words[16] == 0x8FFFFFFFu);
  const std::vector<RayRecord> back = decodeRayRecords(words);
  CHECK(back[1].span == RaySpan::Ahead);
  CHECK(back[2].span == RaySpan::AnyHit);
  CHECK(back[2].id == kMaxRayId);
  // The job word keeps bit 31 of an any-hit ray beside a (bits 30:28), not the ahead bit.
  const ModelHeader identity = makeModelHeader(ModelPlacement{}, 0);
  rays[1].direction = {-1.0f, 0.5f, 0.25f};
  rays[2].direction = {-1.0f, 0.5f, 0.25f};
  CHECK(rayRecordToJob(rays[1], identity).idWord() == (6u | 1u << 28));
  CHECK(rayRecordToJob(rays[2], identity).idWord() == (0x8FFFFFFFu | 1u << 28));
  words[16] |= 1u << 30;
  CHECK_THROWS_WITH(decodeRayRecords(words),
                    Catch::Contains("record 2") && Catch::Contains("both set"));
  TValueRecord anyHitJob;
  anyHitJob.span = RaySpan::AnyHit;
  CHECK_THROWS_AS(encodeJobRecords({anyHitJob}), std::invalid_argument);
}

// With the lights outside the model's cube a shadow segment ends beyond the cube, so for the octree
// (whose first hit is the nearest) any-hit costs what the nearest hit ahead costs; AO segments end
// inside it, and there any-hit stops early.
TEST_CASE("Any-hit rays agree with the nearest hit ahead on hit or miss\\, and cost no more",
          "[secondary]") {
  for (const char* scene : {"menger", "terrain", "sphere"})
    for (RayType type : {RayType::Shadow, RayType::Ao}) {
      const Model model(scene);
      const std::vector<RayRecord> rays = workload(model, type).rays;
      REQUIRE(rays.size() > 100);
      GoldenModel golden(model.image.memory(), GoldenConfig{});
      const auto anyHit = golden.traceRays(rays, GoldenConfig{}.epsilon);
      const auto ahead = golden.traceRays(withSpan(rays, RaySpan::Ahead), GoldenConfig{}.epsilon);
      size_t occluded = 0, cheaper = 0;
      for (size_t i = 0; i < rays.size(); ++i) {
        INFO(scene << " " << toString(type) << " ray " << i);
        const bool aheadWithin = ahead[i].hit && ahead[i].tHit <= (1 << 16);
        REQUIRE(anyHit[i].hit == aheadWithin);
        REQUIRE(anyHit[i].cost <= ahead[i].cost);
        CHECK(anyHit[i].idWord >> 31 == 1);
        occluded += anyHit[i].hit;
        cheaper += anyHit[i].cost < ahead[i].cost;
      }
      CHECK(occluded > 0);
      CHECK(occluded < rays.size());
      CHECK((cheaper > 0) == (type == RayType::Ao));
    }
}

// The decision is the behaviour's: the timed models and the recurrence trace any-hit rays as the
// golden model does, cost included, and count them apart.
TEST_CASE("Every model traces a shadow workload as the golden model and counts its any-hit rays",
          "[secondary]") {
  const Model model("menger");
  std::vector<RayRecord> rays = workload(model, RayType::Shadow, camera(24, 16)).rays;
  const std::vector<RayRecord> primaries = makeFrameRayRecords(camera(24, 16), model.header);
  rays.insert(rays.end(), primaries.begin(), primaries.begin() + 40);  // ids below the shadows'
  GoldenModel golden(model.image.memory(), GoldenConfig{});
  const std::vector<TraversalResult> expected = golden.traceRays(rays, GoldenConfig{}.epsilon);
  uint64_t anyHitHits = 0;
  for (size_t i = 0; i < rays.size(); ++i)
    anyHitHits += rays[i].span == RaySpan::AnyHit && expected[i].hit;
  RtuConfig config;
  config.cores = 4;
  config.memory.ideal = false;
  for (ModelKind kind : {ModelKind::CycleAccurate, ModelKind::LooselyTimed, ModelKind::Golden}) {
    INFO(toString(kind));
    const RtuRun run = runModel(kind, model.image.memory(),
                                std::vector<HostRecord>(rays.begin(), rays.end()), config);
    const std::vector<TraversalResult> results = svoResults(run.results);
    REQUIRE(results.size() == rays.size());
    for (size_t i = 0; i < results.size(); ++i) REQUIRE(results[i] == expected[run.jobIndices[i]]);
    uint64_t anyHitRays = 0, hits = 0;
    for (const CoreStatistics& core : run.statistics.coreTimes) {
      anyHitRays += core.anyHitRays;
      hits += core.anyHitHits;
    }
    CHECK(anyHitRays == rays.size() - 40);
    CHECK(hits == anyHitHits);
  }
}

// The oracle (kinds/svo/svo_voxel_walk.h) walks from where the line enters the cube: walked from
// the light toward the shadow ray's origin, the segment is occluded when it meets a voxel before
// the origin (t < 1). Disagreements only where the walk grazes an edge of the grid.
TEST_CASE("Shadow rays' any-hit answers agree with the voxel walk from the light", "[secondary]") {
  const Model model("menger");
  const std::vector<RayRecord> shadow = workload(model, RayType::Shadow).rays;
  GoldenModel golden(model.image.memory(), GoldenConfig{});
  const auto results = golden.traceRays(shadow, GoldenConfig{}.epsilon);
  size_t unexplained = 0;
  for (size_t i = 0; i < shadow.size(); ++i) {
    const glm::dvec3 origin = vec(shadow[i].origin), toLight = vec(shadow[i].direction);
    const glm::dvec3 light = origin + toLight;
    VoxelWalkOptions options;
    options.tUncertainty.fill(4 * kStep / glm::length(toLight));
    const VoxelWalkResult walk = walkVoxels(model.image.memory(), 0, light, -toLight, options);
    const bool occluded = walk.hit && walk.tHit < 1.0;
    if (occluded != results[i].hit && walk.clearance > 0) ++unexplained;
  }
  CHECK(unexplained == 0);
}

// The reference: the primary hit from the oracle's walk in double, the hit point on the exact
// face, the offset and the new direction written out again here.
TEST_CASE("Secondary rays equal a float64 reference spawn within the format's precision",
          "[secondary]") {
  const Model model("menger");
  const Camera view = camera(40, 24);
  const std::vector<RayRecord> primaries = makeFrameRayRecords(view, model.header);
  const glm::dvec3 light{2.0, 4.0, -3.0};
  std::vector<RayRecord> reflections = workload(model, RayType::Reflection, view).rays;
  std::vector<RayRecord> shadows = workload(model, RayType::Shadow, view).rays;
  size_t compared = 0, shadowIndex = 0;
  for (const RayRecord& reflection : reflections) {
    const RayRecord& primary = primaries[reflection.id];
    const glm::dvec3 o = vec(primary.origin), d = glm::normalize(vec(primary.direction));
    const VoxelWalkResult walk = walkVoxels(model.image.memory(), 0, o, d);
    if (!walk.hit || walk.clearance < 8 * kStep) continue;  // grazing an edge: either voxel
    glm::dvec3 n{0.0};
    n[walk.entryAxis] = d[walk.entryAxis] > 0 ? -1.0 : 1.0;
    const glm::dvec3 spawn = o + walk.tHit * d + 0x1p-12 * n;
    const glm::dvec3 mirrored = d - 2.0 * glm::dot(d, n) * n;
    INFO("pixel " << reflection.id);
    for (int k = 0; k < 3; ++k) {
      // The golden t is within a few steps of the exact one, along a unit direction.
      REQUIRE(std::abs(reflection.origin[k] - spawn[k]) <= 6 * kStep);
      REQUIRE(std::abs(reflection.direction[k] - mirrored[k]) <= 0x1p-23);
    }
    while (shadowIndex < shadows.size() && shadows[shadowIndex].id / 2 < reflection.id)
      ++shadowIndex;
    if (glm::dot(light - spawn, n) > 1e-3) {  // the first light faces the point: a ray to it
      REQUIRE(shadowIndex < shadows.size());
      REQUIRE(shadows[shadowIndex].id == reflection.id * 2);
      for (int k = 0; k < 3; ++k)
        REQUIRE(std::abs(shadows[shadowIndex].direction[k] - (light - spawn)[k]) <= 8 * kStep);
    }
    ++compared;
  }
  CHECK(compared > 300);
}

TEST_CASE("Spawned rays start beyond the hit voxel and never hit it\\, which a line would",
          "[secondary]") {
  const auto [scene, depth] = GENERATE(std::make_pair("menger", 6), std::make_pair("terrain", 8));
  const Model model(scene, depth);
  const Camera view = camera(160, 90);
  const std::vector<RayRecord> primaries = makeFrameRayRecords(view, model.header);
  GoldenModel golden(model.image.memory(), GoldenConfig{});
  std::vector<uint64_t> primaryVoxel(primaries.size());
  for (size_t i = 0; i < primaries.size(); ++i) {
    const auto result = golden.traceRays({primaries[i]}, GoldenConfig{}.epsilon);
    primaryVoxel[i] = result[0].hit ? golden.lastHitVoxel() : ~uint64_t{0};
  }
  for (RayType type : {RayType::Reflection, RayType::Diffuse, RayType::Ao, RayType::Shadow}) {
    const RayWorkload rays = workload(model, type, view);
    size_t selfHits = 0, selfHitsAsLines = 0;
    const uint32_t perHit = type == RayType::Reflection ? 1 : 2;
    for (const RayRecord& ray : rays.rays) {
      const uint64_t own = primaryVoxel[ray.id / perHit];
      selfHits +=
          golden.traceRays({ray}, GoldenConfig{}.epsilon)[0].hit && golden.lastHitVoxel() == own;
      selfHitsAsLines +=
          golden.traceRays(withSpan({ray}, RaySpan::Line), GoldenConfig{}.epsilon)[0].hit &&
          golden.lastHitVoxel() == own;
    }
    INFO(scene << " " << toString(type) << ": " << rays.rays.size() << " rays");
    CHECK(selfHits == 0);
    CHECK(selfHitsAsLines > 0);  // what the span avoids: 6 to 13 % of the rays (workloads.md)
  }
}

TEST_CASE("Sampled rays: cosine-weighted in the hemisphere\\, their length\\, seeded",
          "[secondary]") {
  const Model model("sphere");
  const Camera view = camera(24, 16);
  RayWorkloadSpec spec;
  spec.secondary.type = RayType::Ao;
  spec.secondary.samples = 64;
  spec.secondary.aoDistance = 0.5;
  const RayWorkload ao =
      makeRayWorkload(model.image.memory(), model.header, view, GoldenConfig{}, spec);
  REQUIRE(ao.rays.size() == ao.primaryHits * 64);
  // Over the sphere's hits: cos(theta) to the face's normal has mean 2/3 under cos/pi, and
  // E[cos^2] = 1/2. The face normal: the golden primary hit's axis, against the primary ray.
  const std::vector<RayRecord> primaries = makeFrameRayRecords(view, model.header);
  GoldenModel golden(model.image.memory(), GoldenConfig{});
  const std::vector<TraversalResult> hits = golden.traceRays(primaries, GoldenConfig{}.epsilon);
  double sumCos = 0.0, sumCos2 = 0.0;
  for (const RayRecord& ray : ao.rays) {
    CHECK(ray.span == RaySpan::AnyHit);
    const glm::dvec3 d = vec(ray.direction);
    REQUIRE(glm::length(d) == Approx(0.5).epsilon(1e-6));
    const size_t pixel = ray.id / 64;
    const int axis = hits[pixel].normal[0] ? 0 : hits[pixel].normal[1] ? 1 : 2;
    const double c = d[axis] / 0.5 * (primaries[pixel].direction[axis] > 0 ? -1.0 : 1.0);
    REQUIRE(c > 0.0);
    sumCos += c;
    sumCos2 += c * c;
  }
  const double n = static_cast<double>(ao.rays.size());
  CHECK(sumCos / n == Approx(2.0 / 3.0).margin(0.01));
  CHECK(sumCos2 / n == Approx(0.5).margin(0.01));
  const RayWorkload again =
      makeRayWorkload(model.image.memory(), model.header, view, GoldenConfig{}, spec);
  CHECK(encodeRayRecords(again.rays) == encodeRayRecords(ao.rays));
  spec.secondary.seed = 2;
  const RayWorkload other =
      makeRayWorkload(model.image.memory(), model.header, view, GoldenConfig{}, spec);
  CHECK(encodeRayRecords(other.rays) != encodeRayRecords(ao.rays));

  spec.secondary.type = RayType::Random;
  spec.randomRays = 2000;
  const RayWorkload random =
      makeRayWorkload(model.image.memory(), model.header, view, GoldenConfig{}, spec);
  REQUIRE(random.rays.size() == 2000);
  glm::dvec3 mean{0.0};
  for (const RayRecord& ray : random.rays) {
    CHECK(ray.span == RaySpan::Ahead);
    CHECK(glm::length(vec(ray.direction)) == Approx(1.0).epsilon(1e-6));
    for (int k = 0; k < 3; ++k) REQUIRE(std::abs(ray.origin[k]) <= 1.0f);
    mean += vec(ray.direction);
  }
  CHECK(glm::length(mean / 2000.0) < 0.06);  // 3 sigma of a uniform mean is 0.039 per axis
}

TEST_CASE("Ray orders keep every ray: shuffled is seeded\\, sorted groups octants", "[secondary]") {
  const Model model("menger");
  RayWorkloadSpec spec;
  spec.secondary.type = RayType::Diffuse;
  std::vector<std::vector<RayRecord>> orders;
  for (RayOrder order : {RayOrder::Pixel, RayOrder::Shuffled, RayOrder::Sorted}) {
    spec.order = order;
    orders.push_back(
        makeRayWorkload(model.image.memory(), model.header, camera(40, 24), GoldenConfig{}, spec)
            .rays);
  }
  const auto ids = [](const std::vector<RayRecord>& rays) {
    std::vector<uint32_t> list;
    for (const RayRecord& ray : rays) list.push_back(ray.id);
    return list;
  };
  const std::vector<uint32_t> pixel = ids(orders[0]);
  CHECK(std::is_sorted(pixel.begin(), pixel.end()));
  for (size_t o = 1; o < 3; ++o) {
    std::vector<uint32_t> sorted = ids(orders[o]);
    CHECK(sorted != pixel);
    std::sort(sorted.begin(), sorted.end());
    CHECK(sorted == pixel);
  }
  int octants = 0, lastOctant = -1;
  for (const RayRecord& ray : orders[2]) {
    const int octant =
        (ray.direction[0] < 0) | (ray.direction[1] < 0) << 1 | (ray.direction[2] < 0) << 2;
    REQUIRE(octant >= lastOctant);
    octants += octant != lastOctant;
    lastOctant = octant;
  }
  CHECK(octants > 1);
  CHECK_THROWS_WITH(parseRayOrder("random"), Catch::Contains("pixel, shuffled or sorted"));
  CHECK_THROWS_WITH(parseRayType("glossy"), Catch::Contains("--ray-type glossy"));
}

TEST_CASE("Render passes: primary first\\, each once\\, and each pixel's open share",
          "[secondary]") {
  CHECK(parseRayPasses("primary,shadow,ao", "--passes") ==
        std::vector<RayType>{RayType::Primary, RayType::Shadow, RayType::Ao});
  CHECK_THROWS_WITH(parseRayPasses("shadow", "--passes"), Catch::Contains("first pass is primary"));
  CHECK_THROWS_WITH(parseRayPasses("primary,ao,ao", "--passes"), Catch::Contains("ao twice"));
  CHECK_THROWS_WITH(parseRayPasses("primary,,ao", "--passes"), Catch::Contains("'' is not one of"));
  // Two lights a pixel: pixel 0 sees one of two, pixel 1 one (its second light was behind the
  // face: no ray), pixel 2 has no ray (no hit, or both lights behind): 0.
  PassRun shadow;
  shadow.type = RayType::Shadow;
  shadow.raysPerHit = 2;
  for (uint32_t id : {0u, 1u, 2u}) {
    shadow.rays.emplace_back();
    shadow.rays.back().id = id;
  }
  shadow.hits = {false, true, false};
  CHECK(openShare(shadow, 3) == std::vector<double>{0.5, 0.5, 0.0});
  PassRun ao = shadow;
  ao.type = RayType::Ao;
  CHECK(openShare(ao, 3) == std::vector<double>{0.5, 0.5, 1.0});
}
