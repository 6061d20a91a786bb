// The BVH's golden traversal against the independent oracle (geometry/triangle_oracle.h) on real
// meshes: every ray of four views, random rays, and rays aimed at vertices and edges, traced
// through the langr, binned and lbvh builds' images with each triangle test, against the float64
// brute force over the same float32 triangles. BvhAgreement (docs/triangles.md, "Checking against
// the oracle"): both miss, or both hit the same triangle, or hit two at the same t within 4 float32
// ulp (a shared edge or vertex, or coincident triangles). A disagreement is explained when the
// ray's line passes within 4 float32 ulp of the scene's scale of an edge of a disputed triangle:
// there float32 arithmetic may decide the other way (measured: at most 0.55 ulp on these meshes).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "bvh_meshes.h"
#include "geometry/ray_sets.h"
#include "geometry/triangle_oracle.h"
#include "kinds/bvh/bvh_kind.h"
#include "kinds/bvh/langr_builder.h"
#include "kinds/bvh/lbvh_builder.h"
#include "kinds/bvh/sah_builder.h"
#include "rtu/golden_shell.h"
#include "triangle_margins.h"

namespace rtu {
namespace {

// The mesh as the image holds it: every vertex rounded to float32.
TriangleMesh roundedToFloat(TriangleMesh mesh) {
  for (auto& v : mesh.vertices) v = glm::dvec3(glm::vec3(v));
  return mesh;
}

struct BvhAgreement {
  int same = 0, ties = 0, explained = 0, unexplained = 0;
  int disagreements() const { return explained + unexplained; }
};

class OracleCheck {
 public:
  OracleCheck(const TriangleMesh& mesh, const BuildTree& tree)
      : image_(layOut(tree, mesh)),
        held_(roundedToFloat(mesh)),
        sections_(sectionsOf(BvhImageView(image_.words).header())),
        meshScale_(std::max(largestCoordinate(meshBounds(held_).lower),
                            largestCoordinate(meshBounds(held_).upper))) {}

  // Both sides trace the ray the image's float32 format can carry.
  static Ray carried(const Ray& given) {
    return Ray{glm::dvec3(glm::vec3(given.origin)), glm::dvec3(glm::vec3(given.direction))};
  }

  // The oracle's hits for `rays`, computed once per mesh and ray set (`key`): they do not depend
  // on the builder or the triangle test compared with them.
  const std::vector<std::optional<OracleHit>>& oracleHits(const std::string& key,
                                                          const std::vector<Ray>& rays) const {
    static std::map<std::string, std::vector<std::optional<OracleHit>>> cache;
    auto found = cache.find(key);
    if (found != cache.end()) return found->second;
    std::vector<std::optional<OracleHit>> hits;
    hits.reserve(rays.size());
    for (const Ray& given : rays) hits.push_back(closestHit(held_, carried(given), 0, INFINITY));
    return cache.emplace(key, std::move(hits)).first->second;
  }

  template <class Intersector>
  BvhAgreement compare(const std::vector<Ray>& rays,
                       const std::vector<std::optional<OracleHit>>& oracle) const {
    GoldenShell<BvhKind<Intersector>> shell(image_.memory(), BvhConfig{});
    BvhAgreement agreement;
    for (size_t i = 0; i < rays.size(); ++i) {
      const Ray ray = carried(rays[i]);
      BvhResult result;
      shell.run(0,
                BvhJob{makeBvhRay(glm::vec3(ray.origin), glm::vec3(ray.direction), 0, INFINITY),
                       sections_},
                result);
      classify(result, oracle[i], ray, agreement);
    }
    return agreement;
  }

 private:
  void classify(const BvhResult& result, const std::optional<OracleHit>& oracle, const Ray& ray,
                BvhAgreement& agreement) const {
    if (result.hit == oracle.has_value() && (!oracle || result.primitive == oracle->triangle)) {
      ++agreement.same;
    } else if (result.hit && oracle && std::abs(result.t - oracle->t) <= 4 * ulp(oracle->t)) {
      ++agreement.ties;
    } else {
      double margin = INFINITY;
      if (result.hit) margin = edgeMargin(held_, result.primitive, ray);
      if (oracle) margin = std::min(margin, edgeMargin(held_, oracle->triangle, ray));
      const double scale = std::max(meshScale_, largestCoordinate(ray.origin));
      ++(margin <= 4 * 0x1.0p-23 * scale ? agreement.explained : agreement.unexplained);
    }
  }
  static double ulp(double t) {
    const float f = static_cast<float>(t);
    return std::nextafter(f, INFINITY) - f;
  }

  BvhImage image_;
  TriangleMesh held_;
  BvhSections sections_;
  double meshScale_;
};

}  // namespace

TEST_CASE("BVH golden traversal agrees with the oracle on real meshes", "[bvh_oracle]") {
  const char* name = GENERATE("spider.obj", "WusonOBJ.obj");
  const TriangleMesh& mesh = assimpObjModel(name);
  const std::string builder = GENERATE("langr", "binned", "lbvh");
  const OracleCheck check(mesh, builder == "langr"    ? buildLangr(mesh).tree
                                : builder == "binned" ? buildSah(mesh).tree
                                                      : buildLbvh(mesh).tree);
  const Aabb<double> box = meshBounds(mesh);
  SECTION("views and random rays: no disagreement") {
    std::vector<Ray> rays = viewRays(box, 4, 32, 32);
    const std::vector<Ray> random = randomRays(box, 1000, 2);
    rays.insert(rays.end(), random.begin(), random.end());
    const auto& oracle = check.oracleHits(std::string(name) + " views", rays);
    const BvhAgreement watertight = check.compare<WatertightIntersector>(rays, oracle);
    CHECK(watertight.disagreements() == 0);
    CHECK(watertight.same > 4000);
    CHECK(check.compare<MollerTrumboreIntersector>(rays, oracle).disagreements() == 0);
  }
  SECTION("rays aimed at vertices and edges: none unexplained") {
    const std::vector<Ray> rays = aimedRays(mesh, 2000, 1);
    const auto& oracle = check.oracleHits(std::string(name) + " aimed", rays);
    const BvhAgreement watertight = check.compare<WatertightIntersector>(rays, oracle);
    const BvhAgreement mt = check.compare<MollerTrumboreIntersector>(rays, oracle);
    INFO(name << ' ' << builder << ": watertight same " << watertight.same << " ties "
              << watertight.ties << " explained " << watertight.explained
              << "; Moller-Trumbore same " << mt.same << " ties " << mt.ties << " explained "
              << mt.explained);
    CHECK(watertight.unexplained == 0);
    CHECK(mt.unexplained == 0);
    // Most aimed rays still agree: float32 decides otherwise at 3-6 % of them with the watertight
    // test (spider 114, Wuson 64) and twice as often with Moller-Trumbore (265, 167).
    CHECK(watertight.disagreements() < 150);
    CHECK(mt.disagreements() < 350);
    CHECK(watertight.disagreements() < mt.disagreements());
    CHECK(watertight.ties > 100);  // rays through shared vertices
  }
}

}  // namespace rtu

namespace rtu {

TEST_CASE("BVH golden traversal: a shallow stack drops entries, counted", "[bvh_oracle]") {
  const TriangleMesh& mesh = assimpObjModel("spider.obj");
  const BvhImage image = layOut(buildLangr(mesh).tree, mesh);
  const BvhSections sections = sectionsOf(BvhImageView(image.words).header());
  BvhConfig shallow;
  shallow.stackDepth = 2;
  GoldenShell<BvhKind<WatertightIntersector>> deep(image.memory(), BvhConfig{});
  GoldenShell<BvhKind<WatertightIntersector>> short2(image.memory(), shallow);
  uint64_t droppedDeep = 0, droppedShallow = 0, changed = 0;
  for (const Ray& ray : viewRays(meshBounds(mesh), 2, 32, 32)) {
    const BvhJob job{makeBvhRay(glm::vec3(ray.origin), glm::vec3(ray.direction), 0, INFINITY),
                     sections};
    BvhResult a, b;
    deep.run(0, job, a);
    short2.run(0, job, b);
    droppedDeep += a.counts.dropped;
    droppedShallow += b.counts.dropped;
    const bool same = a.hit == b.hit && a.primitive == b.primitive && a.t == b.t;
    if (b.counts.dropped == 0) CHECK(same);  // nothing lost: the same traversal
    changed += !same;
  }
  CHECK(droppedDeep == 0);
  CHECK(droppedShallow > 0);
  CHECK(changed > 0);
}

}  // namespace rtu
