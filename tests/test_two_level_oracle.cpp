// The two-level BVH's golden traversal (kinds/bvh/two_level_traversal.h) against the float64
// oracle (geometry/triangle_oracle.h) over the flattened world mesh: every instance's triangles
// placed into the world in double, from the float32 vertices its mesh image holds, by the exact
// (double) placement. Four instances of spider.obj overlap, rotated about every axis, one scaled
// by 1/2 and one non-uniformly.
//
// TwoLevelAgreement is test_bvh_oracle.cpp's BvhAgreement rule (both miss; the same instance and
// triangle; or two hits within 4 float32 ulp of t). A disagreement is explained when the ray's line
// passes within the bound below of an edge of a disputed triangle. The mesh traversal's own float32
// bound, 4 ulp of its scale (the mesh's largest coordinate or the model-space origin's), is in
// model units and grows by the instance's largest scale in the world. The transform adds its own:
// the golden traces toModelSpace's float32 ray, not the exact inverse image of the world ray. With
// T, R^T and 1/S each rounded once (relative 2^-24), v = o - T rounded (2^-24 |v|, plus 2^-24 |T|
// from T), each row's dot product of 2 products and 2 sums (3 2^-24 |v|, the row being a unit
// vector) and the scale's product (2^-24), every model-space origin component is within
// (1 + 1 + 1 + 3 + 1 + 1) 2^-24 |v| + 2^-24 |T| of exact, scaled; over 3 components and back in
// world units at most 8 √3 2^-24 |v| + √3 2^-24 |T| < 2^-20 (|o - T| + |T|). The direction's
// relative error is likewise below 2^-20, which moves the line by 2^-20 t |d| at the hit. So:
//   bound = S_max 4 2^-23 max(mesh scale, |o'|) + 2^-20 (|o - T| + |T| + t |d|).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "bvh_meshes.h"
#include "geometry/ray_sets.h"
#include "geometry/triangle_oracle.h"
#include "kinds/bvh/langr_builder.h"
#include "kinds/bvh/sah_builder.h"
#include "kinds/bvh/two_level_traversal.h"
#include "placed_world.h"
#include "triangle_margins.h"

namespace rtu {
namespace {

struct TwoLevelAgreement {
  int same = 0, ties = 0, explained = 0, unexplained = 0;
  double worstSameT = 0;  // the largest relative t difference of agreeing hits
  int disagreements() const { return explained + unexplained; }
};

class TwoLevelOracleCheck {
 public:
  TwoLevelOracleCheck(const TriangleMesh& mesh, const TwoLevelBvh& bvh)
      : mesh_(mesh),
        bvh_(bvh),
        world_(placedWorld({mesh}, bvh.topLevel().instances)),
        meshScale_(std::max(largestCoordinate(meshBounds(mesh).lower),
                            largestCoordinate(meshBounds(mesh).upper))) {}

  const TriangleMesh& world() const { return world_; }

  TwoLevelAgreement compare(const std::vector<Ray>& rays) const {
    TwoLevelTraversal<WatertightIntersector> traversal(bvh_);
    TwoLevelAgreement agreement;
    for (const Ray& given : rays) {
      const glm::vec3 o(given.origin), d(given.direction);
      const Ray ray{glm::dvec3(o), glm::dvec3(d)};  // both sides trace the float32 ray
      const RayRecord record{0, {o.x, o.y, o.z}, {d.x, d.y, d.z}, 0};
      classify(traversal.trace(record, 0, INFINITY), closestHit(world_, ray, 0, INFINITY), ray,
               agreement);
    }
    return agreement;
  }

 private:
  uint32_t flatIndex(const TwoLevelResult& r) const {
    return r.instance * static_cast<uint32_t>(mesh_.triangles.size()) + r.primitive;
  }

  void classify(const TwoLevelResult& result, const std::optional<OracleHit>& oracle,
                const Ray& ray, TwoLevelAgreement& agreement) const {
    if (result.hit == oracle.has_value() && (!oracle || flatIndex(result) == oracle->triangle)) {
      ++agreement.same;
      if (oracle)
        agreement.worstSameT =
            std::max(agreement.worstSameT, std::abs(result.t - oracle->t) / oracle->t);
    } else if (result.hit && oracle && std::abs(result.t - oracle->t) <= 4 * ulp(oracle->t)) {
      ++agreement.ties;
    } else {
      const double t = std::max(result.hit ? double{result.t} : 0.0, oracle ? oracle->t : 0.0);
      bool explained = false;
      if (result.hit) explained |= withinBound(flatIndex(result), ray, t);
      if (oracle) explained |= withinBound(oracle->triangle, ray, t);
      ++(explained ? agreement.explained : agreement.unexplained);
    }
  }

  // Whether the ray passes the flat triangle's edges within the bound of the file's comment.
  bool withinBound(uint32_t flat, const Ray& ray, double t) const {
    const uint32_t instance = flat / static_cast<uint32_t>(mesh_.triangles.size());
    const ModelPlacement& p = bvh_.topLevel().instances[instance].placement;
    const glm::dvec3 v = ray.origin - p.translation;
    const glm::dvec3 model = (glm::transpose(p.rotation) * v) / p.scale;
    const double largestScale = std::max({p.scale.x, p.scale.y, p.scale.z});
    const double bound =
        largestScale * 4 * 0x1.0p-23 * std::max(meshScale_, largestCoordinate(model)) +
        0x1.0p-20 * (glm::length(v) + glm::length(p.translation) + t * glm::length(ray.direction));
    return edgeMargin(world_, flat, ray) <= bound;
  }

  static double ulp(double t) {
    const float f = static_cast<float>(t);
    return std::nextafter(f, INFINITY) - f;
  }

  const TriangleMesh& mesh_;
  const TwoLevelBvh& bvh_;
  TriangleMesh world_;
  double meshScale_;
};

TwoLevelBvh spiderScene(const TriangleMesh& mesh, const BuildTree& tree) {
  std::vector<MeshBvh> meshes;
  meshes.push_back(meshBvh(tree, mesh));
  return TwoLevelBvh(std::move(meshes));
}

}  // namespace

TEST_CASE("Two-level BVH agrees with the oracle over the flattened spiders", "[two_level]") {
  const TriangleMesh& mesh = assimpObjModel("spider.obj");
  const Aabb<double> box = meshBounds(mesh);
  const std::string builder = GENERATE("langr", "binned");
  TwoLevelBvh bvh =
      spiderScene(mesh, builder == "langr" ? buildLangr(mesh).tree : buildSah(mesh).tree);
  bvh.place(overlappingInstances(box, 0));
  const TwoLevelOracleCheck check(mesh, bvh);
  const Aabb<double> world = meshBounds(check.world());
  std::vector<Ray> rays = viewRays(world, 4, 32, 32);
  const std::vector<Ray> random = randomRays(world, 1000, 3);
  rays.insert(rays.end(), random.begin(), random.end());
  const TwoLevelAgreement agreement = check.compare(rays);
  INFO(builder << ": same " << agreement.same << " ties " << agreement.ties << " explained "
               << agreement.explained << " worst relative t " << agreement.worstSameT);
  CHECK(agreement.unexplained == 0);
  CHECK(agreement.same > 4500);
  CHECK(agreement.disagreements() <= 5);
  CHECK(agreement.worstSameT < 0x1.0p-14);  // measured 1.5e-5, on a grazing ray
  SECTION("rays aimed at the world's vertices and edges: none unexplained") {
    const TwoLevelAgreement aimed = check.compare(aimedRays(check.world(), 1000, 4));
    INFO(builder << " aimed: same " << aimed.same << " ties " << aimed.ties << " explained "
                 << aimed.explained);
    CHECK(aimed.unexplained == 0);
    CHECK(aimed.explained < 100);
  }
}

TEST_CASE("Two-level BVH: the next frame's placements, the same mesh image", "[two_level]") {
  const TriangleMesh& mesh = assimpObjModel("spider.obj");
  const Aabb<double> box = meshBounds(mesh);
  TwoLevelBvh bvh = spiderScene(mesh, buildLangr(mesh).tree);
  bvh.place(overlappingInstances(box, 0));
  const uint32_t* image = bvh.meshes()[0].image.words.data();
  bvh.place(overlappingInstances(box, 0.3 * box.extent().x));  // every instance moved along x
  CHECK(bvh.meshes()[0].image.words.data() == image);
  const TwoLevelOracleCheck check(mesh, bvh);
  const TwoLevelAgreement agreement = check.compare(viewRays(meshBounds(check.world()), 2, 32, 32));
  INFO("same " << agreement.same << " explained " << agreement.explained);
  CHECK(agreement.unexplained == 0);
  CHECK(agreement.same > 2000);
}

}  // namespace rtu
