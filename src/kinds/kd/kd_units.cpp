#include "kinds/kd/kd_units.h"

#include "base/float_bits.h"

namespace rtu {
namespace {

float epsilon() { return bitsToFloat(kTrayRacerEpsilonBits); }

// One axis' slab distances, entry first.
KdInterval slab(const KdRay& ray, const std::array<float, 6>& box, int axis, Division division) {
  const float o = ray.origin[axis], d = ray.direction[axis];
  const float t1 = div32(sub32(box[axis], o), d, division).value;
  const float t2 = div32(sub32(box[axis + 3], o), d, division).value;
  return signBit32(d) ? KdInterval{false, t2, t1} : KdInterval{false, t1, t2};
}

}  // namespace

KdInterval sceneIntersection(const KdRay& ray, const std::array<float, 6>& box, KdTMaxClamp clamp,
                             Division division) {
  KdInterval interval = slab(ray, box, 0, division);
  for (int axis = 1; axis < 3; ++axis) {
    const KdInterval a = slab(ray, box, axis, division);
    interval.miss = interval.miss || greater32(interval.tMin, a.tMax) ||
                    greater32(a.tMin, interval.tMax);
    interval.tMin = greater32(interval.tMin, a.tMin) ? interval.tMin : a.tMin;
    interval.tMax = greater32(a.tMax, interval.tMax) ? interval.tMax : a.tMax;
  }
  interval.miss = interval.miss || greater32(epsilon(), interval.tMax);
  interval.tMin = greater32(interval.tMin, epsilon()) ? interval.tMin : epsilon();
  const bool keepExit =
      clamp == KdTMaxClamp::AsBuilt ? greater32(interval.tMax, 1.0f) && !ray.shadow : !ray.shadow;
  if (!keepExit) interval.tMax = 1.0f;
  return interval;
}

KdPlaneTest planeTest(const KdRay& ray, uint32_t axis, float split, float tMin, float tMax,
                      Division division) {
  const float diff = sub32(split, ray.origin[axis]);
  const Quotient mid = div32(diff, ray.direction[axis], division);
  const bool above = signBit32(diff), positive = !signBit32(ray.direction[axis]);
  const bool zero = mid.divisionByZero;
  const bool maxAfterMid = greater32(tMax, mid.value), midAfterMin = greater32(mid.value, tMin);
  KdPlaneTest test;
  test.tMid = mid.value;
  test.onlyLow = (above && !positive && !midAfterMin) || (!above && !positive) ||
                 (!above && zero) || (!above && positive && !maxAfterMid);
  test.onlyHigh = (!above && positive && !midAfterMin) || (above && positive) || (above && zero) ||
                  (above && !positive && !maxAfterMid);
  test.lowThenHigh = !above && positive && maxAfterMid && midAfterMin;
  test.highThenLow = above && !positive && maxAfterMid && midAfterMin;
  return test;
}

KdTriangleHit intersectUnitTriangle(const KdRay& ray, const std::array<float, 12>& matrix,
                                    Division division) {
  const auto& o = ray.origin;
  const auto& d = ray.direction;
  std::array<float, 3> oPrime, dPrime;
  for (int r = 0; r < 3; ++r) {
    const float* m = &matrix[3 * r];
    oPrime[r] =
        add32(add32(mul32(m[0], o[0]), mul32(m[1], o[1])), add32(mul32(m[2], o[2]), matrix[9 + r]));
    dPrime[r] = add32(add32(mul32(m[0], d[0]), mul32(m[1], d[1])), mul32(m[2], d[2]));
  }
  KdTriangleHit found;
  found.t = div32(oPrime[2], -dPrime[2], division).value;
  found.u = add32(oPrime[0], mul32(dPrime[0], found.t));
  found.v = add32(oPrime[1], mul32(dPrime[1], found.t));
  found.hit = greater32(1.0f, add32(found.u, found.v)) && greater32(found.t, epsilon()) &&
              !signBit32(found.u) && !signBit32(found.v);
  return found;
}

}  // namespace rtu
