// The k-d golden traversal against the independent oracle (geometry/triangle_oracle.h) on the
// spider (more triangles and nodes than the seed's hardware holds, so built in the wide format):
// views, random rays and rays aimed at vertices and edges, in hardware space, against the float64
// brute force over the source triangles. Agreement (docs/triangles.md, "k-d tree (seed 001)"):
// both miss or hit the same triangle; or both hit within 4 float32 ulp of the same t (a shared
// edge or vertex); or a disagreement explained by the stored matrices: the ray crosses a disputed
// triangle's plane within `bound` of its edge in unit-triangle coordinates (edgeBound below);
// anything else is unexplained and must not occur. And the short stack: 1 entry or 64, the same
// hits, the shallow one restarting.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <utility>

#include "base/float_bits.h"
#include "bvh_meshes.h"
#include "geometry/mesh_checks.h"
#include "geometry/ray_sets.h"
#include "geometry/triangle_oracle.h"
#include "kinds/kd/kd_kind.h"
#include "kinds/kd/pbrt_kd_builder.h"
#include "rtu/golden_shell.h"
#include "trayracer_r1.h"

namespace rtu {
namespace {

// The spider without its degenerate (and duplicate) triangles, which the oracle never hits.
TriangleMesh checkedSpider() {
  TriangleMesh mesh = assimpObjModel("spider.obj");
  checkTriangleMesh(mesh, "spider.obj", MeshDefectPolicy::Drop);
  return mesh;
}

std::vector<glm::dvec3> cornersOf(const TriangleMesh& mesh) {
  std::vector<glm::dvec3> corners;
  for (const auto& triangle : mesh.triangles)
    for (uint32_t index : triangle) corners.push_back(mesh.vertices[index]);
  return corners;
}

// The mesh in hardware space, as the UTTMs hold it (up to their rounding).
TriangleMesh inHardwareSpace(TriangleMesh mesh) {
  for (auto& v : mesh.vertices) v = toHardwareSpace(v);
  return mesh;
}

KdRay hardwareRay(const Ray& world) {
  const glm::vec3 o(toHardwareSpace(world.origin)), d(toHardwareSpace(world.direction));
  return KdRay{{o.x, o.y, o.z}, {d.x, d.y, d.z}, false};
}

Ray asDouble(const KdRay& ray) {
  const auto v = [](const std::array<float, 3>& a) { return glm::dvec3(a[0], a[1], a[2]); };
  return Ray{v(ray.origin), v(ray.direction)};
}

// `explained`: near an edge. The seed's build also loses triangles the oracle hits: those in no
// leaf's list (`unlisted`: the edge order END before START at equal positions keeps a triangle
// flat on the chosen split's axis and at its position out of both children) and those flat on a
// split plane (`onSplit`: listed on one side only, so a ray crossing the plane
// at the triangle meets it only if it visits that side, which TRAV's rounded t_mid decides).
struct Agreement {
  int same = 0, ties = 0, explained = 0, unlisted = 0, onSplit = 0, unexplained = 0;
  int disagreements() const { return explained + unlisted + onSplit + unexplained; }
};

std::ostream& operator<<(std::ostream& out, const Agreement& a) {
  return out << "same " << a.same << " ties " << a.ties << " explained " << a.explained
             << " unlisted " << a.unlisted << " on a split " << a.onSplit << " unexplained "
             << a.unexplained;
}

// Why the build loses each triangle, if it does.
enum class KdLoss : uint8_t { None, Unlisted, OnSplit };

bool flatOnSplit(const TriangleMesh& hardware, uint32_t triangle, const TrayRacerScene& scene) {
  const auto& ids = hardware.triangles[triangle];
  for (uint32_t axis = 0; axis < 3; ++axis) {
    const float plane = static_cast<float>(hardware.vertices[ids[0]][axis]);
    bool flat = true;
    for (uint32_t id : ids) flat = flat && static_cast<float>(hardware.vertices[id][axis]) == plane;
    if (!flat) continue;
    // Within a narrow split's truncation (19 fraction bits kept) of a split on that axis.
    for (const TrayRacerNode& node : scene.nodes)
      if (!node.leaf && node.axis == axis &&
          std::abs(bitsToFloat(node.splitBits) - plane) <= std::abs(plane) * 0x1.0p-18f)
        return true;
  }
  return false;
}

std::vector<KdLoss> lossesOf(const TriangleMesh& hardware, const TrayRacerScene& scene) {
  std::vector<KdLoss> losses(scene.uttms.size(), KdLoss::Unlisted);
  for (uint32_t id : scene.lists) losses.at(id) = KdLoss::None;
  for (uint32_t i = 0; i < losses.size(); ++i)
    if (losses[i] == KdLoss::None && flatOnSplit(hardware, i, scene)) losses[i] = KdLoss::OnSplit;
  return losses;
}

// Where the ray crosses the triangle's plane, in its exact unit-triangle coordinates, and how far
// the INT unit's u and v may stray from it. The stored entries are float24: each within
// 2^-15 + 2^-24 of its double value relatively (RNE to float, then 8 bits truncated), and each of
// INT's binary32 operations adds at most 2^-24 of a partial sum no greater than the sum of the
// magnitudes of its terms; so, to first order, with e = 2^-14 (above 2^-15 + 7 * 2^-24):
//   o'_r, d'_r stray by e S_r, e D_r (S_r = sum_j |m_rj o_j| + |t_r|, D_r = sum_j |m_rj d_j|);
//   t = o'_z / -d'_z by e t (S_z / |o'_z| + D_z / |d'_z|) + 2^-24 t;
//   u = o'_x + d'_x t by e (S_x + t D_x) + |d'_x| (the error of t) + 2^-23 (|d'_x t| + |u|).
// The bound is the sum of u's and v's, as u + v is tested too.
struct Crossing {
  double margin =
      INFINITY;  // |min(u, v, 1 - u - v)|: inside, to the nearest edge; outside, how far
  double bound = 0;
};

Crossing crossing(const TriangleMesh& hardware, uint32_t triangle, const Ray& ray) {
  const auto& ids = hardware.triangles[triangle];
  const UnitTriangleMatrix m = unitTriangleMatrix(
      hardware.vertices[ids[0]], hardware.vertices[ids[1]], hardware.vertices[ids[2]]);
  std::array<double, 3> o{}, d{}, s{}, ds{};
  for (int r = 0; r < 3; ++r) {
    o[r] = m.t[r];
    s[r] = std::abs(m.t[r]);
    for (int j = 0; j < 3; ++j) {
      o[r] += m.m[r][j] * ray.origin[j];
      d[r] += m.m[r][j] * ray.direction[j];
      s[r] += std::abs(m.m[r][j] * ray.origin[j]);
      ds[r] += std::abs(m.m[r][j] * ray.direction[j]);
    }
  }
  const double t = -o[2] / d[2];
  if (!std::isfinite(t)) return Crossing{};
  const double e = 0x1.0p-14;
  const double tError =
      e * std::abs(t) * (s[2] / std::abs(o[2]) + ds[2] / std::abs(d[2])) + 0x1.0p-24 * std::abs(t);
  Crossing c;
  double bary[2];
  for (int r = 0; r < 2; ++r) {
    bary[r] = o[r] + d[r] * t;
    c.bound += e * (s[r] + std::abs(t) * ds[r]) + std::abs(d[r]) * tError +
               0x1.0p-23 * (std::abs(d[r] * t) + std::abs(bary[r]));
  }
  c.margin = std::abs(std::min({bary[0], bary[1], 1 - bary[0] - bary[1]}));
  return c;
}

// A scene's image checked against the oracle over `mesh`, the scene's triangles in world space in
// the scene's order.
class KdOracleCheck {
 public:
  KdOracleCheck(TriangleMesh mesh, const TrayRacerScene& scene)
      : mesh_(std::move(mesh)),
        hardware_(inHardwareSpace(mesh_)),
        image_(layOutKd(scene)),
        losses_(lossesOf(hardware_, scene)),
        sections_(sectionsOf(decodeKdHeader(image_.words.data()))) {}

  const TriangleMesh& mesh() const { return mesh_; }
  const KdImage& image() const { return image_; }
  KdJob job(const Ray& world) const { return KdJob{hardwareRay(world), sections_}; }

  Agreement compare(const std::vector<Ray>& rays) const {
    GoldenShell<KdKind> shell(image_.memory(), KdTraversalConfig{});
    Agreement agreement;
    for (const Ray& world : rays) {
      const KdJob j = job(world);
      KdResult result;
      shell.run(0, j, result);
      const Ray ray = asDouble(j.ray);
      classify(result, closestHit(hardware_, ray, 0, INFINITY), ray, agreement);
    }
    return agreement;
  }

 private:
  void classify(const KdResult& result, const std::optional<OracleHit>& oracle, const Ray& ray,
                Agreement& agreement) const {
    if (result.hit == oracle.has_value() && (!oracle || result.primitive == oracle->triangle)) {
      ++agreement.same;
    } else if (result.hit && oracle && std::abs(result.t - oracle->t) <= 4 * ulp(oracle->t)) {
      ++agreement.ties;
    } else if ((result.hit && nearEdge(result.primitive, ray)) ||
               (oracle && nearEdge(oracle->triangle, ray))) {
      ++agreement.explained;
    } else if (oracle && losses_[oracle->triangle] == KdLoss::Unlisted) {
      ++agreement.unlisted;
    } else if (oracle && losses_[oracle->triangle] == KdLoss::OnSplit) {
      ++agreement.onSplit;
    } else {
      ++agreement.unexplained;
    }
  }
  bool nearEdge(uint32_t triangle, const Ray& ray) const {
    const Crossing c = crossing(hardware_, triangle, ray);
    return c.margin <= c.bound;
  }
  static double ulp(double t) {
    const float f = static_cast<float>(t);
    return std::nextafter(f, INFINITY) - f;
  }

  TriangleMesh mesh_, hardware_;
  KdImage image_;
  std::vector<KdLoss> losses_;
  KdSections sections_;
};

// The scene a wide file of `mesh` holds (written and read back).
TrayRacerScene wideScene(const TriangleMesh& mesh) {
  const std::vector<glm::dvec3> corners = cornersOf(mesh);
  const KdBuild build = buildPbrtKd(pbrtTriangleBoxes(corners), PbrtKdParameters{});
  const std::vector<glm::dvec3> normals(mesh.triangles.size(), glm::dvec3(0));
  const TrayRacerScene scene = makeTrayRacerScene(build, corners, normals, {});
  return readTrayRacerScene(writeTrayRacerScene(scene, TrayRacerFormat::Wide),
                            TrayRacerFormat::Wide);
}

const KdOracleCheck& spiderCheck() {
  static const KdOracleCheck check(checkedSpider(), wideScene(checkedSpider()));
  return check;
}

// R1's elephant.scene as the hardware read it (narrow: 28-bit splits, K9), over its source
// triangles.
TriangleMesh soupOf(const std::vector<glm::dvec3>& corners) {
  TriangleMesh mesh;
  mesh.vertices = corners;
  for (uint32_t i = 0; i + 2 < corners.size(); i += 3) mesh.triangles.push_back({i, i + 1, i + 2});
  return mesh;
}

}  // namespace

TEST_CASE("k-d golden traversal agrees with the oracle on the spider (wide)", "[kd]") {
  const KdOracleCheck& check = spiderCheck();
  REQUIRE(validateKd(check.image().words).empty());
  const Aabb<double> box = meshBounds(check.mesh());
  SECTION("views and random rays") {
    std::vector<Ray> rays = viewRays(box, 4, 32, 32);
    const std::vector<Ray> random = randomRays(box, 1000, 2);
    rays.insert(rays.end(), random.begin(), random.end());
    const Agreement a = check.compare(rays);
    INFO(a);
    CHECK(a.unexplained == 0);
    CHECK(a.same > 5000);  // measured 5095 of 5096, and 1 explained
    CHECK(a.explained < 5);
  }
  SECTION("rays aimed at vertices and edges") {
    const Agreement a = check.compare(aimedRays(check.mesh(), 2000, 1));
    INFO(a);
    CHECK(a.unexplained == 0);
    // Measured: same 1440, ties 46, explained 514. The matrices' float24 entries move each edge
    // by some 2^-15 of the triangle's size, so a quarter of the rays aimed exactly at an edge or
    // vertex land on the other side (the BVH's float32 vertices: 3-6 %), and shared vertices,
    // seen through two triangles' differently rounded matrices, tie less often than they leave
    // a crack or an overlap.
    CHECK(a.same > 1300);
    CHECK(a.explained < 600);
    CHECK(a.ties > 20);
  }
}

TEST_CASE("k-d short stack: 1 entry or 64, the same hits, more restarts", "[kd]") {
  const KdOracleCheck& check = spiderCheck();
  KdTraversalConfig one;
  one.stackDepth = 1;
  KdTraversalConfig deep;
  deep.stackDepth = 64;
  GoldenShell<KdKind> shallow(check.image().memory(), one), full(check.image().memory(), deep);
  uint64_t restartsShallow = 0, restartsFull = 0, droppedFull = 0, differ = 0;
  for (const Ray& ray : viewRays(meshBounds(check.mesh()), 2, 32, 32)) {
    KdResult a, b;
    shallow.run(0, check.job(ray), a);
    full.run(0, check.job(ray), b);
    differ += a.hit != b.hit || (a.hit && (a.primitive != b.primitive || a.t != b.t));
    restartsShallow += a.counts.restarts;
    restartsFull += b.counts.restarts;
    droppedFull += b.counts.dropped;
  }
  INFO("restarts: 1 entry " << restartsShallow << ", 64 entries " << restartsFull);
  CHECK(differ == 0);
  CHECK(droppedFull == 0);
  CHECK(restartsShallow > restartsFull);
}

TEST_CASE("k-d golden traversal agrees with the oracle on R1's elephant.scene", "[kd][kd_r1]") {
  if (!trayRacerDir()) {
    WARN("RTUSIM_TRAYRACER_DIR unset (scripts/extract_trayracer.sh): R1 files not checked");
    return;
  }
  const std::string dir = trayRacerDir();
  const TriangleMesh mesh = soupOf(elephantSource(dir).corners);
  const KdOracleCheck check(mesh, readTrayRacerScene(readBytes(dir + "/SCENES/elephant.scene"),
                                                     TrayRacerFormat::Narrow));
  REQUIRE(validateKd(check.image().words).empty());
  std::vector<Ray> rays = viewRays(meshBounds(mesh), 4, 32, 32);
  const std::vector<Ray> random = randomRays(meshBounds(mesh), 1000, 2);
  rays.insert(rays.end(), random.begin(), random.end());
  const Agreement views = check.compare(rays);
  const Agreement aimed = check.compare(aimedRays(mesh, 2000, 1));
  INFO("views and random: " << views << "; aimed: " << aimed);
  CHECK(views.unexplained == 0);
  CHECK(aimed.unexplained == 0);
  // Measured: views and random 5,093 the same, 1 explained, 2 unlisted; aimed 1,300 the same,
  // 31 ties, 658 explained, 7 unlisted, 4 on a split. The lost triangles are the ground's (flat
  // at world y = 0.528124, a split of the tree) and three flat at world x = 1.
  CHECK(views.same > 5000);
  CHECK(aimed.unlisted + aimed.onSplit < 20);
}

}  // namespace rtu
