// The triangle kinds' spans (rtu/ray_span.h) on a scene worked by hand: two triangles covering
// the square [-1, 1]^2 corner to corner, at z = 0.3 and z = 0.31 (one leaf in every kind's build),
// and rays along +z at (x, y) = (-0.5, -0.5), inside both. A shadow ray from z = -1 to a light at z
// is blocked when the light lies beyond z = 0.3 and open before it; an any-hit ray meets its first
// triangle in its first test and ends there, where the nearest hit ahead goes on to test the
// other; a ray leaving the near triangle's surface finds it again as a line but not with a span.

#include <catch2/catch.hpp>

#include <optional>
#include <vector>

#include <glm/geometric.hpp>

#include "inputs/secondary_rays.h"
#include "kind_fixture.h"
#include "kinds/bih/explore/bih_scene.h"
#include "kinds/bvh/explore/bvh_scene.h"
#include "kinds/kd/explore/kd_scene.h"
#include "triangle_kind_images.h"

namespace rtu {
namespace {

TriangleMesh twoSheets() {
  TriangleMesh mesh;
  for (double z : {0.3, 0.31}) {
    const uint32_t base = static_cast<uint32_t>(mesh.vertices.size());
    mesh.vertices.push_back({-1.0, -1.0, z});
    mesh.vertices.push_back({1.0, -1.0, z});
    mesh.vertices.push_back({-1.0, 1.0, z});
    mesh.triangles.push_back({base, base + 1, base + 2});
  }
  return mesh;
}

RayRecord rayAlongZ(float fromZ, float length, RaySpan span, uint32_t header) {
  RayRecord record;
  record.origin = {-0.5f, -0.5f, fromZ};
  record.direction = {0.0f, 0.0f, length};
  record.modelAddress = header;
  record.span = span;
  return record;
}

template <class Kind>
typename Kind::Result traced(const KindImage& image, const RayRecord& record) {
  const std::vector<CoreKindResult> results =
      goldenBehindSetup<Kind>(image.memory(), kindConfig<Kind>(), {HostRecord(record)});
  return std::get<typename Kind::Result>(results.front());
}

// The hits of `results` (a triangle kind's, of `primaries`: unit directions) on `mesh` (world
// space), each with its triangle: point from the hit's distance, the face's normal toward the
// ray.
template <class Kind>
std::vector<std::pair<SurfaceHit, uint32_t>> triangleHits(
    const std::vector<HostRecord>& primaries, const std::vector<CoreKindResult>& results,
    const TriangleMesh& mesh) {
  std::vector<std::pair<SurfaceHit, uint32_t>> hits;
  for (size_t i = 0; i < results.size(); ++i) {
    const auto& result = std::get<typename Kind::Result>(results[i]);
    if (!Kind::hitAhead(result)) continue;
    const RayRecord& ray = std::get<RayRecord>(primaries[i]);
    SurfaceHit hit;
    hit.pixel = ray.id;
    hit.incoming = glm::dvec3(ray.direction[0], ray.direction[1], ray.direction[2]);
    hit.point = glm::dvec3(ray.origin[0], ray.origin[1], ray.origin[2]) +
                Kind::hitDistance(result, typename Kind::Config{}) * hit.incoming;
    const auto& corner = mesh.triangles[result.primitive];
    const glm::dvec3 a = mesh.vertices[corner[0]];
    hit.normal =
        glm::normalize(glm::cross(mesh.vertices[corner[1]] - a, mesh.vertices[corner[2]] - a));
    if (glm::dot(hit.normal, hit.incoming) > 0) hit.normal = -hit.normal;
    hits.emplace_back(hit, result.primitive);
  }
  return hits;
}

// How many of the rays spawned from `hits` (one each, by `settings`, traced with `span`) hit the
// triangle they leave first.
template <class Kind>
size_t selfHits(const typename KindFixture<Kind>::Frame& frame,
                const std::vector<std::pair<SurfaceHit, uint32_t>>& hits,
                const SecondarySettings& settings, RaySpan span, uint32_t header) {
  std::vector<SurfaceHit> points;
  for (const auto& hit : hits) points.push_back(hit.first);
  std::vector<HostRecord> rays;
  for (RayRecord ray : spawnSecondaryRays(points, settings, header)) {
    ray.span = span;
    rays.emplace_back(ray);
  }
  REQUIRE(rays.size() == hits.size());
  const auto results = goldenBehindSetup<Kind>(frame.memory(), kindConfig<Kind>(), rays);
  size_t count = 0;
  for (size_t i = 0; i < results.size(); ++i) {
    const auto& result = std::get<typename Kind::Result>(results[i]);
    count += result.hit && result.primitive == hits[i].second;
  }
  return count;
}

// Each kind's way off a surface, as its frame's passes take it (KindScene<Kind>::kSelfOffset,
// docs/workloads.md): the BVH's span starts at kBvhSpanTMin, so no offset; the BIH and the k-d
// core (whose EPSILON is 1e-20) take the offset along the normal of the SVO's spawns, 2^-12 world
// units (the BIH's grid offset of 2 units is finer than a float32 record's origin can hold at
// n = 29: docs/workloads.md).
template <class Kind>
void offsetFor(SecondarySettings& settings) {
  settings.selfOffset = KindScene<Kind>::kSelfOffset;
}

}  // namespace

TEMPLATE_TEST_CASE("Reflected rays spawned with the kind's offset never hit their own triangle",
                   "[spans]", BvhKind<>, BihKind<>, KdKind) {
  // From the golden hits of a frame on the sphere's voxel faces, the mirror rays: started on the
  // hit point (2^-40 off the surface) and traced as lines, some hit the triangle they leave;
  // with the kind's offset and a span, none does.
  using Fixture = KindFixture<TestType>;
  const auto frame = Fixture::frame("sphere", 6, 64, 48);
  const auto primaries = Fixture::golden(frame.memory(), kindConfig<TestType>(), frame.jobs);
  const auto hits = triangleHits<TestType>(frame.jobs, primaries, frame.mesh);
  const uint32_t header = std::get<RayRecord>(frame.jobs.front()).modelAddress;
  SecondarySettings settings;
  settings.type = RayType::Reflection;
  settings.selfOffset = 0x1p-40;
  const size_t onSurface = selfHits<TestType>(frame, hits, settings, RaySpan::Line, header);
  offsetFor<TestType>(settings);
  const size_t offset = selfHits<TestType>(frame, hits, settings, RaySpan::Ahead, header);
  INFO(hits.size() << " hits: " << onSurface << " self-hits on the surface, " << offset
                   << " with the offset");
  CHECK(hits.size() > 300);
  CHECK(onSurface > 0);
  CHECK(offset == 0);
}

TEMPLATE_TEST_CASE("A shadow ray is blocked by a triangle before its light and open beyond it",
                   "[spans]", BvhKind<>, BihKind<>, KdKind) {
  const KindImage image = kindImage<TestType>(twoSheets());
  // From z = -1: the light at z = 1 (t at the near sheet 1.3 / 2 = 0.65), at z = 0.305 between
  // the sheets (t = 1.3 / 1.305), at z = 0 (the sheet at t = 1.3, beyond the light), and from
  // z = 1 toward a light at z = 2 (the sheets behind the origin).
  const auto shadow = [&](float fromZ, float lightZ) {
    return traced<TestType>(image, rayAlongZ(fromZ, lightZ - fromZ, RaySpan::AnyHit, image.header));
  };
  CHECK(shadow(-1.0f, 1.0f).hit);
  CHECK(shadow(-1.0f, 0.305f).hit);
  CHECK_FALSE(shadow(-1.0f, 0.0f).hit);
  CHECK_FALSE(shadow(1.0f, 2.0f).hit);
  // The result's id word marks an any-hit ray, and the counts count it, occluded or not.
  CHECK(shadow(-1.0f, 1.0f).idWord == kAnyHitBit);
  CHECK(shadow(-1.0f, 1.0f).counts.anyHit == 1);
  CHECK(shadow(-1.0f, 1.0f).counts.occluded == 1);
  CHECK(shadow(-1.0f, 0.0f).counts.anyHit == 1);
  CHECK(shadow(-1.0f, 0.0f).counts.occluded == 0);
  // The same segment as a line (no span) takes the nearest hit beyond the light.
  const auto line = traced<TestType>(image, rayAlongZ(-1.0f, 1.0f, RaySpan::Line, image.header));
  CHECK(line.hit);
  CHECK(line.idWord == 0);
}

TEMPLATE_TEST_CASE("An any-hit ray ends at its first hit: one triangle test of the leaf's two",
                   "[spans]", BvhKind<>, BihKind<>, KdKind) {
  const KindImage image = kindImage<TestType>(twoSheets());
  const auto anyHit =
      traced<TestType>(image, rayAlongZ(-1.0f, 2.0f, RaySpan::AnyHit, image.header));
  const auto ahead = traced<TestType>(image, rayAlongZ(-1.0f, 2.0f, RaySpan::Ahead, image.header));
  REQUIRE(anyHit.hit);
  REQUIRE(ahead.hit);
  // Both sheets lie in the one leaf and the ray crosses both: the nearest hit tests both, the
  // any-hit ray stops at whichever the leaf lists first.
  CHECK(ahead.counts.triangleTests == 2);
  CHECK(anyHit.counts.triangleTests == 1);
  CHECK(anyHit.cost < ahead.cost);
}

TEST_CASE("A BVH ray with a span leaving a surface does not find it again", "[spans]") {
  // From a point of the near sheet toward -z: as a line the sheet is hit at t = 0; with a span
  // the ray starts at kBvhSpanTMin and meets nothing.
  const KindImage image = kindImage<BvhKind<>>(twoSheets());
  const auto leaving = [&](RaySpan span) {
    return traced<BvhKind<>>(image, rayAlongZ(0.3f, -1.0f, span, image.header));
  };
  const BvhResult line = leaving(RaySpan::Line);
  REQUIRE(line.hit);
  CHECK(line.t == 0.0f);
  CHECK_FALSE(leaving(RaySpan::Ahead).hit);
  CHECK_FALSE(leaving(RaySpan::AnyHit).hit);
}

TEST_CASE("Seed 004's offset moves each coordinate 2 grid units toward the normal's side",
          "[spans]") {
  // O[k] = h[k] + ((n . w > 0) ^ (n[k] < 0) ? 2 : -2), a spawned ray leaving on the normal's side
  // (n . w > 0): +2 where n[k] >= 0, -2 where n[k] < 0; here a grid unit is 0.25 world units and
  // the offset along the normal 1/64.
  SurfaceHit hit;
  hit.point = {1.0, 2.0, 3.0};
  hit.normal = {0.6, -0.8, 0.0};
  SecondarySettings settings;
  settings.selfOffset = 1.0 / 64;
  settings.gridOffset = 2 * 0.25;
  const glm::dvec3 origin = spawnOrigin(hit, settings);
  CHECK(origin.x == 1.0 + 0.6 / 64 + 0.5);
  CHECK(origin.y == 2.0 - 0.8 / 64 - 0.5);
  CHECK(origin.z == 3.0 + 0.5);
}

}  // namespace rtu
