// The k-d golden traversal against the independent oracle (geometry/triangle_oracle.h) on the
// spider (more triangles and nodes than the seed's hardware holds, so built in the wide format):
// views, random rays and rays aimed at vertices and edges, in hardware space, against the float64
// brute force over the source triangles, by kd_oracle_check.h's rule of agreement. And the short
// stack: 1 entry or 64, the same hits, the shallow one restarting.
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
#include "kd_oracle_check.h"
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
    const KdAgreement a = check.compare(rays);
    INFO(a);
    CHECK(a.unexplained == 0);
    CHECK(a.same > 5000);  // measured 5095 of 5096, and 1 explained
    CHECK(a.explained < 5);
  }
  SECTION("rays aimed at vertices and edges") {
    const KdAgreement a = check.compare(aimedRays(check.mesh(), 2000, 1));
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
  const KdAgreement views = check.compare(rays);
  const KdAgreement aimed = check.compare(aimedRays(mesh, 2000, 1));
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
