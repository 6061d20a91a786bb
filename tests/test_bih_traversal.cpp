// The golden BIH traversal (kinds/bih/bih_traversal.h) on the hand scene of bih_hand_scene.h
// (leaves of one triangle; the tree and words of test_bih_builder.cpp and test_bih_image.cpp):
// every state sequence, distance, result and counter derived by hand below against Table 3.1's
// transitions; the access-width contract; ties to the later triangle.
//
// The tree: root (x, clip0 9, clip1 11, children 1, 2); node 1 (x, 6, 2, children 3, 4); node 2
// (y, 4, 3, children 5, 6); leaves 3-6 hold T0-T3. kFourBitC99: directions at scale 2^15, C = 4,
// idir = 2^20 / ω (truncated), 2^20 on an axis the ray does not move along; a distance is
// ((plane - pos) idir) >> 4, floored. Rays straight down (ω = (0, 0, -2^15), idir_z = -32) from
// z = 10 are clipped to the box at z = 3, 7 world units on; their aabb tmax is
// min((15 - x) 2^16, (7 - y) 2^16, (-3)(-32) >> 4 = 6) = 6, twice the 3 grid units to z = 0.
#include <catch2/catch.hpp>

#include <vector>

#include "access_width_check.h"
#include "bih_hand_scene.h"
#include "geometry/ray_sets.h"
#include "kinds/bih/bih_kind.h"
#include "rtu/golden_shell.h"

namespace rtu {
namespace {

using C99BihKind = BihKind<C99Intersector>;
using S = BihState;

struct HandScene {
  TriangleMesh mesh = bihHandMesh();
  SceneGrid grid;
  ProjectedMesh projected = projectMesh(mesh, grid);
  BihImage image;

  explicit HandScene(uint32_t leafSize = 1, const FixedTriangleFormat& format = kFourBitC99)
      : grid(meshBounds(mesh), format),
        image(layOut(buildBih(triangleBoxes(mesh, grid, projected), sceneUpper(grid),
                              BihBuildSettings{leafSize}),
                     projected, grid)) {}

  BihJob job(const Ray& world) const {
    return BihJob{grid.quantise(world).value(), sceneOf(decodeBihHeader(image.words.data()))};
  }
};

Ray down(double x, double y) { return Ray{{x, y, 10}, {0, 0, -1}}; }

struct Trace {
  BihResult result;
  std::vector<BihState> states;  // each state as it is stepped
};

// One cycle a state: a ray's cost is its count of states (the kind's cycles: test_bih_kind.cpp).
BihConfig statesOnly() {
  BihConfig config;
  config.cycles = BihCycles{1, 1};
  return config;
}

template <class TracedKind = C99BihKind>
Trace trace(const HandScene& scene, const Ray& world, BihConfig config = statesOnly()) {
  typename TracedKind::Behaviour traversal = TracedKind::behaviour(config);
  const BihJob job = scene.job(world);
  traversal.start(job);
  const WordMemory memory(scene.image.words);
  Trace out;
  while (traversal.busy()) {
    out.states.push_back(traversal.state());
    traversal.step([&](uint32_t address) { return memory.read(address); });
  }
  traversal.finish();
  TracedKind::writeResult(5, traversal, out.result);
  return out;
}

const std::vector<BihState> kOneTriangle = {S::Leaf, S::Tri0, S::Tri1, S::Tri2, S::Test};

std::vector<BihState> operator+(std::vector<BihState> a, const std::vector<BihState>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

TEST_CASE("BIH traversal: both children of node 1, pushed and popped", "[bih]") {
  const HandScene scene;
  // Down at (3, 1). Root: dist0 = ty = (9 - 3) 2^16 >= tmin 0, dist1 = tx = (11 - 3) 2^16 > tmax
  // 6: near only, node 1 (idir_x >= 0: the near child is c). Node 1: dist0 = ty = (6 - 3) 2^16,
  // dist1 = tx = (2 - 3) 2^16 = -65536 <= 6: both; push {4, max(0, -65536) = 0, 6}, tmax =
  // min(6, 196608) = 6, PUSH to node 3 (T0). T0 at z = 0: t = 3, hit, tBest 3. POP: node 4 (T1) at
  // z = 2: t = 1 <= 3, hit. The stack is empty: done.
  const Trace run = trace(scene, down(3, 1));
  CHECK(run.states ==
        std::vector<BihState>{S::Aabb, S::Node, S::Inner, S::Node, S::Inner, S::Push, S::Node} +
            kOneTriangle + std::vector<BihState>{S::Pop, S::Node} + kOneTriangle);
  CHECK(run.result.idWord == 5);
  CHECK(run.result.hit);
  CHECK(run.result.primitive == 1);
  CHECK(run.result.t == 1);
  // T1 (legs 7, edges 65536 / 7 -> 9362): k = (3 - 2, 1 - 0) = (1, 1), u = e1p k_q = 9362,
  // v = e2q k_p = 9362.
  CHECK(run.result.u == 9362);
  CHECK(run.result.v == 9362);
  CHECK(run.result.cost == 19);
  CHECK(run.result.counts.nodes == 4);
  CHECK(run.result.counts.pushes == 1);
  CHECK(run.result.counts.pops == 1);
  CHECK(run.result.counts.leaves == 2);
  CHECK(run.result.counts.triangleTests == 2);
  CHECK(run.result.counts.errBits == 0);
  CHECK(run.result.counts.tOverflows == 0);
  CHECK(scene.job(down(3, 1)).ray.worldT(run.result.t) == 8.0);  // 7 to the box, 1 in it
}

TEST_CASE("BIH traversal: the far child only", "[bih]") {
  const HandScene scene;
  // Down at (7, 1). Root: dist0 = (9 - 7) 2^16 >= 0, dist1 = (11 - 7) 2^16 > 6: node 1. Node 1:
  // dist0 = ty = (6 - 7) 2^16 < tmin 0, dist1 = tx = (2 - 7) 2^16 <= 6: far only, tmin =
  // max(0, dist1) = 0, node c + 1 = 4 (T1): t = 1, k = (5, 1), u = 9362, v = 5 9362 = 46810,
  // u + v = 56172, >> E = 28086 <= 2^15: a hit.
  const Trace run = trace(scene, down(7, 1));
  CHECK(run.states ==
        std::vector<BihState>{S::Aabb, S::Node, S::Inner, S::Node, S::Inner, S::Node} +
            kOneTriangle);
  CHECK(run.result.primitive == 1);
  CHECK(run.result.u == 9362);
  CHECK(run.result.v == 46810);
  CHECK(run.result.cost == 11);
  CHECK(run.result.counts.nodes == 3);
  CHECK(run.result.counts.pushes == 0);
  CHECK(run.result.counts.leaves == 1);
}

TEST_CASE("BIH traversal: both children missed with the stack empty ends the ray", "[bih]") {
  const HandScene scene;
  // Down at (10, 1), between the root's clip planes: dist0 = (9 - 10) 2^16 < 0 and dist1 =
  // (11 - 10) 2^16 > 6. AABB, NODE, INNER, done.
  const Trace run = trace(scene, down(10, 1));
  CHECK(run.states == std::vector<BihState>{S::Aabb, S::Node, S::Inner});
  CHECK_FALSE(run.result.hit);
  CHECK(run.result.cost == 3);
  CHECK(run.result.counts.nodes == 1);
  CHECK(run.result.counts.triangleTests == 0);
}

TEST_CASE("BIH traversal: a ray going -x takes the right child as the near one", "[bih]") {
  const HandScene scene;
  // From (19, 1, 6) along (-4, 0, -3): it enters the box at (15, 1, 3), t_clip = 1. ω = (-0.8,
  // 0, -0.6) 2^15 -> (-26214, 0, -19661); idir = 2^20 / ω -> (-40, 2^20, -53). AABB: x: -15 -40
  // = 600 >> 4 = 37; y: 6 2^16; z: -3 -53 = 159 >> 4 = 9; tmax = 9. Root: idir_x < 0, so dist0 =
  // tx = (11 - 15)(-40) >> 4 = 10 >= 0 and dist1 = ty = (9 - 15)(-40) >> 4 = 15 > 9: near only,
  // the near child c + 1 = node 2, tmax = min(9, 10) = 9. Node 2 (y): dist0 = (4 - 1) 2^16,
  // dist1 = (3 - 1) 2^16 > 9: near only, node 5 (T2, z = 1). C99: num = (1 - 3) 2^15, den =
  // -19661, t = 65536 / 19661 = 3.33 -> 3; k_p = 15 + ((3 -26214) >> 15 = -3) - 11 = 1, k_q = 1;
  // edges 1/4 = 16384: u = v = 16384.
  const Trace run = trace(scene, Ray{{19, 1, 6}, {-4, 0, -3}});
  CHECK(run.states ==
        std::vector<BihState>{S::Aabb, S::Node, S::Inner, S::Node, S::Inner, S::Node} +
            kOneTriangle);
  CHECK(run.result.primitive == 2);
  CHECK(run.result.t == 3);
  CHECK(run.result.u == 16384);
  CHECK(run.result.v == 16384);
  CHECK(run.result.counts.nodes == 3);
}

TEST_CASE("BIH traversal: one leaf of four, and ties to the later triangle", "[bih]") {
  SECTION("the default leaf size: the root is a leaf, all four tested in list order") {
    const HandScene scene(4);
    // Down at (3, 1): T0 hits at 3, T1 at 1, T2 and T3 miss (x < 11).
    const Trace run = trace(scene, down(3, 1));
    CHECK(run.states == std::vector<BihState>{S::Aabb, S::Node} + kOneTriangle + kOneTriangle +
                            kOneTriangle + kOneTriangle);
    CHECK(run.result.primitive == 1);
    CHECK(run.result.counts.leaves == 1);
    CHECK(run.result.counts.triangleTests == 4);
  }
  SECTION("two triangles in one plane: the later listed wins") {
    HandScene scene(4);
    // Triangle T1's record copied over T0's (source id kept 0): both hit at t = 1.
    const BihHeader header = decodeBihHeader(scene.image.words.data());
    auto* records = scene.image.words.data() + header.triangleBase;
    std::copy(records + 12, records + 23, records);
    std::swap(scene.image.words[header.listBase], scene.image.words[header.listBase + 1]);
    // The list is now 1, 0, 2, 3: T1 (source 1) first, then the copy (source 0).
    const Trace run = trace(scene, down(3, 1));
    CHECK(run.result.t == 1);
    CHECK(run.result.primitive == 0);
  }
}

TEST_CASE("BIH traversal: every state reads within one aligned access", "[bih]") {
  const HandScene scene;
  C99BihKind::Behaviour traversal = C99BihKind::behaviour(BihConfig{});
  traversal.start(scene.job(down(3, 1)));
  const int reads = wordsReadWithinAccesses(traversal, WordMemory(scene.image.words));
  CHECK(reads == 4 * 3 + 2 * (1 + 12));  // 4 node triples, 2 list entries, 2 records
}

}  // namespace rtu

namespace rtu {

// The VHDL kernel (Listing A.2) as the traversal's intersector, on the hand scene at kFourBitVhdl.
// Its rules, from fixed_kernels.h and t_div.h: for a plane z = z0 (r = z, np = nq = 0) nom =
// z0 - O_z and den = ω_z; t_div sets the error bit when their signs differ or |nom| >= |den|, i.e.
// unless t = nom / den lies in [0, 2^(n+1)) = [0, 32) (t = 0 passes only with den > 0, C9);
// t = floor(|nom| 2^5 / |den|); k = (O_p - pp, O_q - pq) + (floor(t / 2) ω >> 4) (t without its
// LSB, C8); u = e1p k_q, v = e2q k_p with e = 1/a at scale 2^6 (a = 6: 11, 7: 9, 4: 16, 3: 21); a
// hit needs u + v < 2^6 strictly (C10).
using VhdlKind = BihKind<VhdlIntersector>;

TEST_CASE("BIH traversal, VHDL kernel: the hand scene's push and pop, t and u, v", "[bih]") {
  const HandScene scene(1, kFourBitVhdl);
  // Down at (3, 1), clipped at z = 3. The BIH distances are exact grid t here (idir_z = -16,
  // idir_x = 511): the same path as the C99 case above. T0 (z = 0): t = 3, k = (3, 1), u = 11,
  // v = 33, u + v = 44 < 64: a hit. T1 (z = 2): t = 1 <= 3, k = (1, 1), u = v = 9: the hit.
  const Trace run = trace<VhdlKind>(scene, down(3, 1));
  CHECK(run.states ==
        std::vector<BihState>{S::Aabb, S::Node, S::Inner, S::Node, S::Inner, S::Push, S::Node} +
            kOneTriangle + std::vector<BihState>{S::Pop, S::Node} + kOneTriangle);
  CHECK(run.result.hit);
  CHECK(run.result.primitive == 1);
  CHECK(run.result.t == 1);
  CHECK(run.result.u == 9);
  CHECK(run.result.v == 9);
  CHECK(run.result.cost == 19);
  CHECK(run.result.counts.triangleTests == 2);
  CHECK(run.result.counts.errBits == 0);
}

TEST_CASE("BIH traversal, VHDL kernel: t = 0 ahead of a rising ray is a hit (C9)", "[bih]") {
  // Up at (3, 1) from z = -10, clipped at z = 0: ω_z = +1 saturates to 31. T0 lies in the origin's
  // plane: nom = 0, den = 31, no error, t = 0, k = (3, 1): a hit at t = 0. T1 (z = 2): t =
  // floor(2 32 / 31) = 2 > 0: not ahead of the best. C99 rejects t = 0 and takes T1.
  const Ray up{{3, 1, -10}, {0, 0, 1}};
  const Trace vhdl = trace<VhdlKind>(HandScene(1, kFourBitVhdl), up);
  CHECK(vhdl.result.hit);
  CHECK(vhdl.result.primitive == 0);
  CHECK(vhdl.result.t == 0);
  CHECK(vhdl.result.counts.triangleTests == 2);
  CHECK(vhdl.result.counts.errBits == 0);
  const Trace c99 = trace(HandScene(), up);
  CHECK(c99.result.primitive == 1);
}

TEST_CASE("BIH traversal, VHDL kernel: u + v = 1 misses, a plane behind errs", "[bih]") {
  // Down at (12, 3) from z = 3. Root: dist0 = (9 - 12) 511 >> 4 = -96 < 0, dist1 = (11 - 12) 511
  // >> 4 = -32 <= 3: far only, node 2. Node 2 (y): dist0 = (4 - 3) 511 >> 4 = 31, dist1 = 0: both;
  // push node 6. T2 (z = 1, corner (11, 0), a = 4): t = 2, k = (1, 3), u = 16 3 = 48, v = 16, u +
  // v = 64 = 1 exactly: outside (C99 accepts it). T3 (z = 3) passes through the origin: nom = 0
  // against den = -32, signs differ: the divider's error bit. No hit.
  const Trace run = trace<VhdlKind>(HandScene(1, kFourBitVhdl), down(12, 3));
  CHECK(run.states ==
        std::vector<BihState>{S::Aabb, S::Node, S::Inner, S::Node, S::Inner, S::Push, S::Node} +
            kOneTriangle + std::vector<BihState>{S::Pop, S::Node} + kOneTriangle);
  CHECK_FALSE(run.result.hit);
  CHECK(run.result.counts.triangleTests == 2);
  CHECK(run.result.counts.errBits == 1);
  const Trace c99 = trace(HandScene(), down(12, 3));
  CHECK(c99.result.primitive == 2);  // its u + v <= 1 + 2^-(m-1)
}

TEST_CASE("BIH traversal, VHDL kernel: t at or beyond 2^(n+1) = 32 errs", "[bih]") {
  // From (0, 1, 3) along (1, 0, -1/16): ω = (31.9, 0, -2.0) -> (31 saturated, 0, -2), idir =
  // (16, 511, -256). AABB tmax = min(15 16 >> 4, 6 511 >> 4, 3 256 >> 4) = 15. Root: dist0 = 9,
  // dist1 = 11: both, push {node 2, 11, 15}. Node 1: dist0 = 6, dist1 = 2: both, push {node 4, 2,
  // 9}. T0 (z = 0): |nom| = 3 >= |den| = 2, t would be 48: error. T1 (z = 2): t = 1 32 / 2 = 16, k
  // = (0 - 2 + (8 31 >> 4 = 15), 1) = (13, 1), u + v = 9 + 117 >= 64: outside. Node 2 (y): dist0 =
  // (4 - 1) 511 >> 4 = 95 >= 11, dist1 = 63 > 15: near only, T2 (z = 1): |nom| = 2 = |den|, t
  // would be 32 = 2^(n+1): error.
  const Trace run = trace<VhdlKind>(HandScene(1, kFourBitVhdl), Ray{{0, 1, 3}, {1, 0, -0.0625}});
  CHECK_FALSE(run.result.hit);
  CHECK(run.result.counts.nodes == 6);  // the root, 1, 3, 4, 2, 5
  CHECK(run.result.counts.pushes == 2);
  CHECK(run.result.counts.pops == 2);
  CHECK(run.result.counts.leaves == 3);
  CHECK(run.result.counts.triangleTests == 3);
  CHECK(run.result.counts.errBits == 2);
}

}  // namespace rtu
