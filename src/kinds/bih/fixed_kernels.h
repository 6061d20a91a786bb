#pragma once
// Seed 004's fixed-point ray/triangle test, Badouel's in Wald's projected form (S4 §2 p.23,
// Eqs. 2.1 and 2.2 L221-242): t = (d - O_r - O_p np - O_q nq) / (ω_r + ω_p np + ω_q nq), then
// k_p = O_p + t ω_p - pp, k_q likewise, u = e1p k_q - e1q k_p, v = e2q k_p - e2p k_q. u weighs
// x2 and v weighs x1 (spec 004 §3.1), so rtusim's barycentrics (hit = (1-u-v) v0 + u v1 + v v2)
// are (v, u) / 2^(m-1+E) (rtusimBarycentrics). Two kernels, as each of the seed's listings
// computes it (plan reading C6: they round differently and are not bit-identical):
//
// c99Test   S4 §2.3 p.29 L367-403, 64-bit intermediates (128 where n = 30 needs them):
//           den = (ω_r + (ω_p np >> (m-1)) + (ω_q nq >> (m-1))) >> T, each product floored;
//           den = 0 misses. num = ((d - O_r) << (m-1)) - O_p np - O_q nq, shifted >> T and masked
//           with ~(2^(m-1) - 1) (plan reading C5: the printed masks are OCR-damaged), i.e.
//           floored once to a multiple of 2^T grid units; t = num / den truncated toward zero as
//           C's `/`. A t beyond int32 misses (C7, counted as TOverflow; the listing's `int t`
//           would keep its low bits). Accepted only if 0 < t <= tBest: a later triangle at an
//           equal t replaces the earlier one. k_p = O_p + ((t ω_p) >> (m-1)) - pp in an int (GCC
//           keeps the low 32 bits), u and v in 64 bits; a miss if u < 0, v < 0 or
//           ((u + v) >> E) > 2^(m-1), which accepts u + v up to 1 + (2^E - 1) 2^-(m-1+E). The
//           sum u + v is taken exactly (the listing's long long could only overflow for k far
//           outside the grid, where the exact sum misses).
// vhdlTest  Listing A.2 p.52ff (spec 004 §3.4, reg0-reg8), for m = n + 2 and T = 0: nom =
//           d - (O_r + (O_p np >> (m-1)) + (O_q nq >> (m-1))) floors each product (not the sum);
//           den = ω_r + (ω_p np >> (m-1)) + (ω_q nq >> (m-1)); t_div (t_div.h, w = n + 3) gives
//           t = floor(|nom| / |den|) with its error bit, set for t outside [0, 2^(n+1)) and for
//           den = 0. reg5 multiplies t without its LSB: k_p = (O_p - pp) +
//           ((floor(t/2) ω_p) >> (m-2)) (C8, literally). u = e1p k_q - e1q k_p and v = e2q k_p -
//           e2p k_q at full width (C11: the OCR prints e2q k_p twice; Eq. 2.2 decides; the
//           output ports' low m bits are not the barycentrics). A hit is: no error bit, u >= 0,
//           v >= 0 and bits n+m+1 .. E+m-1 of u + v all zero, i.e. u + v < 1 strictly (C10).
//           There is no t > 0 and no t <= t_best test inside the unit (C9): t = 0 with a
//           positive den is a hit. The unit's t port carries bits n+2 .. 1 of the divider's
//           output (t without its LSB); the result here keeps the divider's whole t.

#include <cstdint>
#include <utility>

#include "kinds/bih/fixed_format.h"
#include "kinds/bih/grid.h"
#include "kinds/bih/projected_triangle.h"
#include "kinds/bih/t_div.h"

namespace rtu {

// Why a test ended; every verdict but Hit is a miss.
enum class FixedVerdict {
  Hit,
  ZeroDenominator,  // c99: den = 0
  TOverflow,        // c99: the quotient does not fit the listing's int t (C7)
  NotAhead,         // c99: t <= 0 or t > tBest
  DividerError,     // vhdl: t_div's error bit (t < 0, t >= 2^(n+1), den = 0)
  Outside,          // the barycentric test failed
};

struct FixedTest {
  FixedVerdict verdict = FixedVerdict::Outside;
  int64_t t = 0;         // grid units; set once the division is done
  int64_t u = 0, v = 0;  // scale 2^(m-1+E); set when the barycentric test ran
  bool hit() const { return verdict == FixedVerdict::Hit; }
};

// What the VHDL's registers keep (plan reading C3). Widened (default): every register as wide as
// its value can grow, so pre_den holds an L2-unit direction's |den| up to sqrt(3) and the
// numerator's sum up to 3 2^n. Literal: each register wraps at its declared width: t1, t2,
// pre_nom, kp, kq n+2 bits; nom n+3; t3, t4, pre_den m; den m+1 (sign-extended pre_den);
// u, v and their sum n+m+2.
enum class VhdlRegisters { Widened, Literal };

struct VhdlOptions {
  VhdlRegisters registers = VhdlRegisters::Widened;
  TDivModel divider = TDivModel::Exact;
};

// The largest t the C99 listing's `int` holds: the natural tBest before any hit.
inline constexpr int64_t kC99NoHitYet = INT32_MAX;

FixedTest c99Test(const FixedTriangleFormat& format, const GridRay& ray,
                  const ProjectedTriangle& triangle, int64_t tBest);
// Throws std::invalid_argument when format.m != n + 2 or T != 0.
FixedTest vhdlTest(const FixedTriangleFormat& format, const GridRay& ray,
                   const ProjectedTriangle& triangle, const VhdlOptions& options = {});

// rtusim's (u, v): the weights of v1 and v2, i.e. the seed's (v, u) / 2^(m-1+E).
std::pair<double, double> rtusimBarycentrics(const FixedTest& test,
                                             const FixedTriangleFormat& format);

}  // namespace rtu
