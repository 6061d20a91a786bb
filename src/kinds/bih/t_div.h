#pragma once
// The VHDL's divider `t_div` (S4 §3.2 p.38-39 L510-533; Listing A.1 p.51): w-bit two's-complement
// numerator a and denominator b, a non-restoring divider of w - 1 add/subtract steps that only
// computes quotients below 2^(w-1) and raises an error bit otherwise, "requiring a < b" (L517,
// L527). In the triangle unit w = n + 3 and b is at scale 2^(m-1) = 2^(w-2), so q is t in grid
// units.
//
// Two models (plan reading C12: the listing's loop header and the first stage's update were lost
// in the OCR):
//   Exact    q = floor(|a| 2^(w-2) / |b|), err = sign(a) xor sign(b) or |a| >= |b| (which covers
//            b = 0). This is what the listing computes whenever |b| <= 2^(w-2).
//   Literal  the listing bit by bit: a (2w-3)-bit register qn = |a| followed by w - 2 zeros and
//            the (w-1)-bit |b|; stage w-2 subtracts |b| from the window qn(2w-4 .. w-2) (the
//            lost update, read as the loop body's first step: non-restoring division begins by
//            subtracting); stage i = w-3 .. 0 subtracts |b| from, or when bit i+w-1 (the
//            previous remainder's sign) is 1 adds it to, the window qn(i+w-2 .. i), modulo
//            2^(w-1); q = not qn(2w-4 .. w-2). The remainder window has no guard bit: for
//            |b| > 2^(w-2) a remainder can reach -|b| < -2^(w-2), its sign is lost and q is
//            wrong (the denominators of an L2-unit direction reach sqrt(3), plan reading C3).
// |x| of a w-bit pattern is taken in w - 1 bits as the listing does (not(x) + 1), so -2^(w-1)
// becomes 0. The output's error bit is the first stage's sign, set by the overflow test
// |a| >= |b| (A.1, "detect overflow and set sign bit"); the listing's `d = ZERO` output branch
// (commented out with its constant) would only repeat it.

#include <cstdint>

namespace rtu {

enum class TDivModel { Exact, Literal };

struct TDivResult {
  bool err = false;
  uint64_t q = 0;  // w - 1 bits; meaningful only without err (Exact then returns 0)
};

TDivResult tDivide(int64_t a, int64_t b, int w, TDivModel model);

}  // namespace rtu
