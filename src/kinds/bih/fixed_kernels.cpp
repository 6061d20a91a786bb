#include "kinds/bih/fixed_kernels.h"

#include <cmath>
#include <stdexcept>

#include "kinds/bih/fixed_arith.h"

namespace rtu {
namespace {

// The ray's origin and direction in the triangle's (r, p, q) order (reg0's swizzle in A.2).
struct Permuted {
  Int128 originR, originP, originQ, omegaR, omegaP, omegaQ;
};

Permuted permute(const GridRay& ray, const ProjectedTriangle& t) {
  const uint32_t r = t.r, p = (r + 1) % 3, q = (r + 2) % 3;
  return {ray.origin[r], ray.origin[p], ray.origin[q], ray.omega[r], ray.omega[p], ray.omega[q]};
}

FixedTest verdict(FixedVerdict v, int64_t t = 0) {
  FixedTest out;
  out.verdict = v;
  out.t = t;
  return out;
}

}  // namespace

FixedTest c99Test(const FixedTriangleFormat& f, const GridRay& ray, const ProjectedTriangle& tri,
                  int64_t tBest) {
  const Permuted o = permute(ray, tri);
  const int shift = f.m - 1;
  const Int128 den = floorShift(
      o.omegaR + floorShift(o.omegaP * tri.np, shift) + floorShift(o.omegaQ * tri.nq, shift), f.T);
  if (den == 0) return verdict(FixedVerdict::ZeroDenominator);
  const Int128 num = (tri.d - o.originR) * pow2(shift) - o.originP * tri.np - o.originQ * tri.nq;
  // `>> T` then `& mask`, the mask clearing the low m - 1 bits: a floor to a multiple of 2^(m-1).
  const Int128 masked = floorShift(floorShift(num, f.T), shift) * pow2(shift);
  const Int128 t = masked / den;
  if (t > INT32_MAX || t < INT32_MIN) return verdict(FixedVerdict::TOverflow);
  if (!(t <= tBest && t > 0)) return verdict(FixedVerdict::NotAhead, static_cast<int64_t>(t));
  const int64_t kp = wrapSigned(o.originP + floorShift(t * o.omegaP, shift) - tri.pp, 32);
  const int64_t kq = wrapSigned(o.originQ + floorShift(t * o.omegaQ, shift) - tri.pq, 32);
  FixedTest out = verdict(FixedVerdict::Outside, static_cast<int64_t>(t));
  out.u = tri.e1p * kq - tri.e1q * kp;  // |int32 x int32| < 2^62: exact in 64 bits
  out.v = tri.e2q * kp - tri.e2p * kq;
  if (out.u >= 0 && out.v >= 0 && floorShift(Int128(out.u) + out.v, f.E) <= pow2(shift))
    out.verdict = FixedVerdict::Hit;
  return out;
}

FixedTest vhdlTest(const FixedTriangleFormat& f, const GridRay& ray, const ProjectedTriangle& tri,
                   const VhdlOptions& options) {
  if (f.m != f.n + 2 || f.T != 0)
    throw std::invalid_argument("the VHDL kernel needs m = n + 2 and T = 0");
  const bool literal = options.registers == VhdlRegisters::Literal;
  const auto reg = [literal](Int128 value, int bits) -> Int128 {
    return literal ? wrapSigned(value, bits) : value;
  };
  const int n = f.n, m = f.m;
  const Permuted o = permute(ray, tri);
  // reg1-reg3: the two dot products, each product floored on its own.
  const Int128 t1 = reg(floorShift(o.originP * tri.np, m - 1), n + 2);
  const Int128 t2 = reg(floorShift(o.originQ * tri.nq, m - 1), n + 2);
  const Int128 nom = reg(tri.d - reg(t1 + t2 + o.originR, n + 2), n + 3);
  const Int128 t3 = reg(floorShift(o.omegaP * tri.np, m - 1), m);
  const Int128 t4 = reg(floorShift(o.omegaQ * tri.nq, m - 1), m);
  const Int128 den = reg(t3 + t4 + o.omegaR, m);  // den = pre_den sign-extended to m + 1 bits
  // reg4: the divider.
  const TDivResult division =
      tDivide(static_cast<int64_t>(nom), static_cast<int64_t>(den), n + 3, options.divider);
  if (division.err) return verdict(FixedVerdict::DividerError);
  // reg5-reg6: t without its LSB times ω, shifted by m - 2.
  const Int128 half = division.q >> 1;
  const Int128 kp = reg(o.originP - tri.pp + reg(floorShift(half * o.omegaP, m - 2), m), n + 2);
  const Int128 kq = reg(o.originQ - tri.pq + reg(floorShift(half * o.omegaQ, m - 2), m), n + 2);
  // reg7-reg8 and the output's hit test.
  FixedTest out = verdict(FixedVerdict::Outside, static_cast<int64_t>(division.q));
  const Int128 u = reg(tri.e1p * kq - tri.e1q * kp, n + m + 2);
  const Int128 v = reg(tri.e2q * kp - tri.e2p * kq, n + m + 2);
  const Int128 sum = reg(u + v, n + m + 2);
  out.u = static_cast<int64_t>(u);
  out.v = static_cast<int64_t>(v);
  if (u >= 0 && v >= 0 && sum >= 0 && sum < pow2(f.E + m - 1)) out.verdict = FixedVerdict::Hit;
  return out;
}

std::pair<double, double> rtusimBarycentrics(const FixedTest& test,
                                             const FixedTriangleFormat& format) {
  const int scale = format.m - 1 + format.E;
  return {std::ldexp(static_cast<double>(test.v), -scale),
          std::ldexp(static_cast<double>(test.u), -scale)};
}

}  // namespace rtu
