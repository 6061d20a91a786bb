// The k-d golden traversal (kinds/kd/kd_traversal.h) on the hand scene (kd_hand_scene.h): SINT's
// interval and its t_max clamp, TRAV's plane test, each ray's states, addresses and counters, all
// derived by hand from the rules in kd_traversal.h.
#include <catch2/catch.hpp>

#include <vector>

#include "kd_hand_scene.h"
#include "kinds/kd/kd_kind.h"
#include "rtu/golden_shell.h"

namespace rtu {
namespace {

KdRay alongX(float x, float y, float z, float speed = 1) {
  return KdRay{{x, y, z}, {speed, 0, 0}, false};
}

struct KdStateTrace {
  std::vector<KdState> states;
  std::vector<uint32_t> addresses;  // of the reading states, in order
  KdTraversal traversal;
};

KdStateTrace trace(const KdRay& ray, int stackDepth) {
  static const KdImage image = layOutKd(handKdScene());
  KdTraversalConfig config;
  config.stackDepth = stackDepth;
  KdStateTrace t{{}, {}, KdTraversal(config)};
  t.traversal.start(KdJob{ray, sectionsOf(decodeKdHeader(image.words.data()))});
  const WordMemory memory = image.memory();
  while (t.traversal.busy()) {
    t.states.push_back(t.traversal.state());
    if (t.traversal.readsMemory()) t.addresses.push_back(t.traversal.memoryAddress());
    t.traversal.step([&memory](uint32_t a) { return memory.read(a); });
  }
  return t;
}

using S = KdState;
const std::vector<S> kTriangle = {S::List, S::Uttm0, S::Uttm1, S::Uttm2, S::Int};

template <class T>
std::vector<T> joined(std::initializer_list<std::vector<T>> parts) {
  std::vector<T> all;
  for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
  return all;
}

// UTTM addresses: the section at 32, 12 words a triangle.
std::vector<uint32_t> uttmReads(uint32_t list, uint32_t triangle) {
  const uint32_t base = 32 + 12 * triangle;
  return {28 + list, base, base + 4, base + 8};
}

}  // namespace

// SINT of a ray from (0, 0.75, 0.75) along +x: x gives [0/1, 8/1]; y and z divide by +0 (no
// swap: its sign bit is clear) to [-inf, +inf], so the interval stays [0, 8]; t_min = EPSILON
// since 0 is not above it. At speed 16 the exit is 0.5, which the as-built clamp makes 1.
TEST_CASE("k-d SINT: interval, EPSILON, the t_max clamp, a miss", "[kd]") {
  const std::array<float, 6> box{0, 0, 0, 8, 2, 2};
  const float epsilon = bitsToFloat(kTrayRacerEpsilonBits);
  KdInterval i =
      sceneIntersection(alongX(0, 0.75f, 0.75f), box, KdTMaxClamp::AsBuilt, Division::Ieee);
  CHECK_FALSE(i.miss);
  CHECK(i.tMin == epsilon);
  CHECK(i.tMax == 8);
  i = sceneIntersection(alongX(0, 0.75f, 0.75f, 16), box, KdTMaxClamp::AsBuilt, Division::Ieee);
  CHECK(i.tMax == 1);
  i = sceneIntersection(alongX(0, 0.75f, 0.75f, 16), box, KdTMaxClamp::Intended, Division::Ieee);
  CHECK(i.tMax == 0.5f);
  // y = 3 is above the box: y's interval is [-inf, -inf], and the entry 0 > -inf.
  CHECK(sceneIntersection(alongX(0, 3, 0.5f), box, KdTMaxClamp::AsBuilt, Division::Ieee).miss);
  // From x = -4 along -x: x gives 4 / -1 and 12 / -1, swapped to [-12, -4]; EPSILON > -4.
  CHECK(sceneIntersection(alongX(-4, 1, 1, -1), box, KdTMaxClamp::AsBuilt, Division::Ieee).miss);
}

// Split 2 over [0.5, 8]: from x = 0 along +x, t_mid = 2 lies inside: low then high; from x = 3,
// diff = -1 (above) with d > 0: only high; along -x from x = 3: t_mid = 1 inside, high then low;
// with d = +0 the divider's division-by-zero flag keeps the origin's side only (x = 1 low, x = 3
// high). From x = 0 over [2, 8], t_mid = 2 is not above t_min: only high.
TEST_CASE("k-d TRAV: the plane test's four decisions", "[kd]") {
  const auto test = [](KdRay ray, float tMin, float tMax) {
    const KdPlaneTest p = planeTest(ray, 0, 2, tMin, tMax, Division::Ieee);
    return std::vector<bool>{p.onlyLow, p.onlyHigh, p.lowThenHigh, p.highThenLow};
  };
  using V = std::vector<bool>;
  CHECK(test(alongX(0, 0, 0), 0.5f, 8) == V{false, false, true, false});
  CHECK(test(alongX(3, 0, 0), 0.5f, 8) == V{false, true, false, false});
  CHECK(test(alongX(3, 0, 0, -1), 0.5f, 8) == V{false, false, false, true});
  CHECK(test(alongX(1, 0, 0, 0), 0.5f, 8) == V{true, false, false, false});
  CHECK(test(alongX(3, 0, 0, 0), 0.5f, 8) == V{false, true, false, false});
  CHECK(test(alongX(0, 0, 0), 2, 8) == V{false, true, false, false});
  CHECK(planeTest(alongX(0, 0, 0), 0, 2, 0.5f, 8, Division::Ieee).tMid == 2);
}

// From (0, 0.75, 0.75): y + z = 1.5 misses T0, T1, T3 (s = 1) and hits T2 (s = 2) at t = 7 with
// u = v = 0.375. Node 0: t_mid 4, low then high: push {4, 8}; the restart node becomes 0 with
// t_max_scene 8. Node 1 over [EPSILON, 4]: t_mid 2, low then high: push {3, 4}. Leaf 2 misses: pop
// {3, 4} with t_min 2; leaf 3 misses twice: pop {4, 8} with t_min 4; leaf 4 hits at 7 <= 8.
TEST_CASE("k-d traversal: a ray's states, addresses and counters by hand", "[kd]") {
  const KdStateTrace t = trace(alongX(0, 0.75f, 0.75f), 4);
  CHECK(t.states == joined<S>({{S::Sint, S::Node, S::Trav, S::Node, S::Trav, S::Node},
                               kTriangle,
                               {S::Pop, S::Node},
                               kTriangle,
                               kTriangle,
                               {S::Pop, S::Node},
                               kTriangle}));
  const std::vector<uint32_t> addresses = joined<uint32_t>({{16, 18, 20},
                                                            uttmReads(0, 0),
                                                            {22},
                                                            uttmReads(1, 1),
                                                            uttmReads(2, 3),
                                                            {24},
                                                            uttmReads(3, 2)});
  CHECK(t.addresses == addresses);
  CHECK(t.traversal.hit());
  CHECK(t.traversal.primitive() == 2);
  CHECK(t.traversal.t() == 7);
  CHECK(t.traversal.u() == 0.375f);
  CHECK(t.traversal.v() == 0.375f);
  CHECK(t.traversal.cost() == 30);
  const KdRayCounts c = t.traversal.counts();
  CHECK(c.nodes == 5);
  CHECK(c.leaves == 3);
  CHECK(c.triangleTests == 4);
  CHECK(c.pushes == 2);
  CHECK(c.restarts == 0);
  CHECK(c.dropped == 0);
  CHECK(c.boxMisses == 0);
}

// With a stack of 1 the push {3, 4} overwrites {4, 8}. After leaf 3 the stack is empty and
// 4 < t_max_scene 8: restart at node 0 over [4, 8], where t_mid = 4 is not above t_min = 4:
// only high, to leaf 4 directly. Two more states (node 0 and its TRAV) than with 4 entries.
TEST_CASE("k-d traversal: a shallow stack loses an entry and restarts", "[kd]") {
  const KdStateTrace t = trace(alongX(0, 0.75f, 0.75f), 1);
  CHECK(t.states == joined<S>({{S::Sint, S::Node, S::Trav, S::Node, S::Trav, S::Node},
                               kTriangle,
                               {S::Pop, S::Node},
                               kTriangle,
                               kTriangle,
                               {S::Pop, S::Node, S::Trav, S::Node},
                               kTriangle}));
  CHECK(t.traversal.hit());
  CHECK(t.traversal.primitive() == 2);
  CHECK(t.traversal.t() == 7);
  CHECK(t.traversal.cost() == 32);
  const KdRayCounts c = t.traversal.counts();
  CHECK(c.nodes == 6);
  CHECK(c.restarts == 1);
  CHECK(c.dropped == 1);
}

// From (0, 1.5, 1.5) every triangle misses (T2: 0.75 + 0.75 = 1.5 is not below 1): after leaf 4
// the stack is empty and its t_max 8 >= t_max_scene 8, a definite miss, one POP after the 30
// states of the ray above. From (2.5, 0.25, 0.25): node 0 pushes {4, 5.5}, node 1 (diff -0.5,
// above) sends it high only; T1 and T3 both hit at 0.5 (o'_z = -0.25 * 2.5 + 0.75 = 0.125 over
// 0.25) and the tie goes to the later, T3.
TEST_CASE("k-d traversal: a definite miss, a tie to the later triangle, a box miss", "[kd]") {
  const KdStateTrace miss = trace(alongX(0, 1.5f, 1.5f), 4);
  CHECK_FALSE(miss.traversal.hit());
  CHECK(miss.traversal.cost() == 31);
  CHECK(miss.states.back() == S::Pop);
  CHECK(miss.traversal.counts().restarts == 0);

  const KdStateTrace tie = trace(alongX(2.5f, 0.25f, 0.25f), 4);
  CHECK(tie.states ==
        joined<S>({{S::Sint, S::Node, S::Trav, S::Node, S::Trav, S::Node}, kTriangle, kTriangle}));
  CHECK(tie.traversal.hit());
  CHECK(tie.traversal.primitive() == 3);
  CHECK(tie.traversal.t() == 0.5f);
  CHECK(tie.traversal.u() == 0.25f);
  CHECK(tie.traversal.v() == 0.25f);

  const KdStateTrace outside = trace(alongX(0, 3, 0.5f), 4);
  CHECK(outside.states == std::vector<S>{S::Sint});
  CHECK(outside.traversal.counts().boxMisses == 1);
  CHECK_FALSE(outside.traversal.hit());
}

TEST_CASE("k-d kind: the golden shell writes the traversal's result", "[kd]") {
  const KdImage image = layOutKd(handKdScene());
  GoldenShell<KdKind> shell(image.memory(), KdTraversalConfig{});
  KdResult result;
  shell.run(7, KdJob{alongX(0, 0.75f, 0.75f), sectionsOf(decodeKdHeader(image.words.data()))},
            result);
  CHECK(result.idWord == 7);
  CHECK(result.hit);
  CHECK(result.primitive == 2);
  CHECK(result.t == 7);
  CHECK(result.cost == 30);
  CHECK(result.counts.leaves == 3);
}

}  // namespace rtu
