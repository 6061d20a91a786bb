// Seed 004's fixed-point ray/triangle kernels (kinds/bih/fixed_kernels.h) and the divider model
// (kinds/bih/t_div.h) on hand cases at n = 4 (grid 0..15), m = 6, E = 2: directions and normals
// at scale 2^5 = 32 (so -32 is -1 exactly), edges at scale 2^7 = 128, u + v = 1 at 2^7 = 128,
// the VHDL divider w = n + 3 = 7 bits and t valid in [0, 2^5 = 32).
#include <catch2/catch.hpp>

#include <stdexcept>

#include "bih_formats.h"
#include "kinds/bih/fixed_kernels.h"

namespace rtu {
namespace {

GridRay gridRay(const GridPoint& origin, const GridPoint& omega) {
  GridRay ray;
  ray.origin = origin;
  ray.omega = omega;
  return ray;
}

// The triangle (px, py, z), (px + 8, py, z), (px, py + 8, z): n = (0, 0, 64), r = 2, p = x,
// q = y; np = nq = 0; d = z; e1p = 8/64 = 1/8 = 16 codes, e1q = 0, e2p = 0, e2q = 16.
ProjectedTriangle flatTriangle(int64_t z, uint32_t px = 0, uint32_t py = 0) {
  ProjectedTriangle t;
  t.r = 2;
  t.pp = px;
  t.pq = py;
  t.d = z;
  t.e1p = 16;
  t.e2q = 16;
  return t;
}

const GridPoint kDown{0, 0, -32};  // -1 exactly

}  // namespace

TEST_CASE("BIH kernels: an interior hit at t = 1", "[bih]") {
  // O = (2, 2, 15) down onto z = 14. C99: den = -32; num = (14 - 15) 32 = -32, t = 1;
  // kp = kq = 2; u = 16 * 2 = 32, v = 32; (u + v) >> 2 = 16 <= 32. VHDL: nom = 14 - 15 = -1,
  // t = floor(1 * 32 / 32) = 1, the same k, u and v, u + v = 64 < 128.
  const GridRay ray = gridRay({2, 2, 15}, kDown);
  for (const FixedTest& test : {c99Test(kFourBit, ray, flatTriangle(14), kC99NoHitYet),
                                vhdlTest(kFourBit, ray, flatTriangle(14))}) {
    CHECK(test.hit());
    CHECK(test.t == 1);
    CHECK(test.u == 32);
    CHECK(test.v == 32);
    // rtusim's (u, v) = the seed's (v, u) / 128: the point (2, 2) is 2/8 along each leg.
    CHECK(rtusimBarycentrics(test, kFourBit) == std::make_pair(0.25, 0.25));
  }
  // C99 accepts t <= tBest, so a later triangle at the same t wins; t > tBest misses.
  CHECK(c99Test(kFourBit, ray, flatTriangle(14), 1).hit());
  CHECK(c99Test(kFourBit, ray, flatTriangle(14), 0).verdict == FixedVerdict::NotAhead);
}

TEST_CASE("BIH kernels: t = 2^(n+1) - 1 is the VHDL's last t, 2^(n+1) its error", "[bih]") {
  // O_z = 0 down onto d = -31 (a record by hand: the plane lies outside the grid, the arithmetic
  // does not care). C99: t = (-31 * 32) / -32 = 31. VHDL: |nom| = 31 < |den| = 32, no error,
  // t = floor(31 * 32 / 32) = 31; k = (2, 2): hits.
  const GridRay ray = gridRay({2, 2, 0}, kDown);
  const FixedTest c99Last = c99Test(kFourBit, ray, flatTriangle(-31), kC99NoHitYet);
  const FixedTest vhdlLast = vhdlTest(kFourBit, ray, flatTriangle(-31));
  CHECK(c99Last.hit());
  CHECK(c99Last.t == 31);
  CHECK(vhdlLast.hit());
  CHECK(vhdlLast.t == 31);
  // d = -32: t = 32. C99 has no upper bound but tBest; the divider's |nom| = 32 >= |den| sets
  // the error bit.
  const FixedTest c99Beyond = c99Test(kFourBit, ray, flatTriangle(-32), kC99NoHitYet);
  CHECK(c99Beyond.hit());
  CHECK(c99Beyond.t == 32);
  CHECK(vhdlTest(kFourBit, ray, flatTriangle(-32)).verdict == FixedVerdict::DividerError);
}

TEST_CASE("BIH kernels: den = 0 (parallel): C99 misses, the VHDL's divider errs", "[bih]") {
  // ω = (1/2, 0, 0) against a plane z = 14: den = 0 + (16 * 0 >> 5) + 0 = 0.
  const GridRay ray = gridRay({2, 2, 15}, {16, 0, 0});
  CHECK(c99Test(kFourBit, ray, flatTriangle(14), kC99NoHitYet).verdict ==
        FixedVerdict::ZeroDenominator);
  CHECK(vhdlTest(kFourBit, ray, flatTriangle(14)).verdict == FixedVerdict::DividerError);
}

TEST_CASE("BIH kernels: u + v = 1 exactly: C99 hits, the VHDL misses", "[bih]") {
  // O = (4, 4, 15): t = 1, k = (4, 4) on the hypotenuse x + y = 8; u = v = 16 * 4 = 64,
  // u + v = 128 = 1. C99: 128 >> 2 = 32, not > 32: a hit. VHDL: bit 7 of the sum is set.
  const GridRay ray = gridRay({4, 4, 15}, kDown);
  const FixedTest c99 = c99Test(kFourBit, ray, flatTriangle(14), kC99NoHitYet);
  const FixedTest vhdl = vhdlTest(kFourBit, ray, flatTriangle(14));
  CHECK(c99.hit());
  CHECK(vhdl.verdict == FixedVerdict::Outside);
  CHECK(c99.u + c99.v == 128);
  CHECK(vhdl.u + vhdl.v == 128);
  // (9, 2): v = 16 * 9 = 144, u = 32: 176 >> 2 = 44 > 32, outside for both.
  const GridRay beyond = gridRay({9, 2, 15}, kDown);
  CHECK(c99Test(kFourBit, beyond, flatTriangle(14), kC99NoHitYet).verdict == FixedVerdict::Outside);
  CHECK(vhdlTest(kFourBit, beyond, flatTriangle(14)).verdict == FixedVerdict::Outside);
  // From (2, 2), the triangle moved to x = 4: kp = 2 - 4 = -2, v = 16 * -2 = -32 < 0.
  CHECK(
      c99Test(kFourBit, gridRay({2, 2, 15}, kDown), flatTriangle(14, 4, 0), kC99NoHitYet).verdict ==
      FixedVerdict::Outside);
}

TEST_CASE("BIH kernels: t = 0: C99 misses, the VHDL hits when den > 0", "[bih]") {
  // The origin on the plane z = 15, ω = (0, 0, 1/2): den = 16. C99: num = 0, t = 0, not > 0.
  // VHDL: nom = 0, signs equal, |0| < 16: t = 0 without error; k = (2, 2): a hit (C9).
  const GridRay up = gridRay({2, 2, 15}, {0, 0, 16});
  CHECK(c99Test(kFourBit, up, flatTriangle(15), kC99NoHitYet).verdict == FixedVerdict::NotAhead);
  const FixedTest vhdl = vhdlTest(kFourBit, up, flatTriangle(15));
  CHECK(vhdl.hit());
  CHECK(vhdl.t == 0);
  // With den < 0 the divider's sign bit is 0 xor 1: an error, even at t = 0.
  CHECK(vhdlTest(kFourBit, gridRay({2, 2, 15}, kDown), flatTriangle(15)).verdict ==
        FixedVerdict::DividerError);
  // Behind the origin: t = (14 - 10) 32 / -32 = -4. C99: not ahead; VHDL: signs differ.
  const GridRay below = gridRay({2, 2, 10}, kDown);
  CHECK(c99Test(kFourBit, below, flatTriangle(14), kC99NoHitYet).verdict == FixedVerdict::NotAhead);
  CHECK(vhdlTest(kFourBit, below, flatTriangle(14)).verdict == FixedVerdict::DividerError);
}

TEST_CASE("BIH kernels: C99's T and its int t", "[bih]") {
  // T = 1: den = -32 >> 1 = -16; num = -32 >> 1 = -16, masked to a multiple of 2^(m-1) = 32:
  // -32; t = -32 / -16 = 2. The numerator keeps multiples of 2^T grid units, so t = 1 becomes 2.
  FixedTriangleFormat dropOne = kFourBit;
  dropOne.T = 1;
  CHECK(c99Test(dropOne, gridRay({2, 2, 15}, kDown), flatTriangle(14), kC99NoHitYet).t == 2);
  // den = 1 code and d - O_z = 2^27: t = 2^27 * 32 / 1 = 2^32 does not fit the listing's int.
  CHECK(
      c99Test(kFourBit, gridRay({2, 2, 0}, {0, 0, 1}), flatTriangle(int64_t(1) << 27), kC99NoHitYet)
          .verdict == FixedVerdict::TOverflow);
  CHECK_THROWS_AS(vhdlTest(dropOne, gridRay({2, 2, 15}, kDown), flatTriangle(14)),
                  std::invalid_argument);
}

TEST_CASE("BIH kernels: the VHDL's register widths and divider with |den| > 1", "[bih]") {
  // np = 1/2 (16 codes), d = 15, O = (0, 0, 14): nom = 15 - (14 + 0 + 0) = 1. ω = (8, 0, 30):
  // den = 30 + (8 * 16 >> 5) = 30 + 4 = 34 > 32, i.e. 1.06.
  ProjectedTriangle tilted = flatTriangle(15);
  tilted.np = 16;
  const GridRay ray = gridRay({0, 0, 14}, {8, 0, 30});
  // Widened registers, exact divider: t = floor(32 / 34) = 0; k = (0, 0): the vertex x0, hit.
  const FixedTest widened = vhdlTest(kFourBit, ray, tilted);
  CHECK(widened.hit());
  CHECK(widened.t == 0);
  // Literal registers: pre_den = 34 wraps in m = 6 bits to -30; the signs differ: an error.
  CHECK(vhdlTest(kFourBit, ray, tilted, {VhdlRegisters::Literal, TDivModel::Exact}).verdict ==
        FixedVerdict::DividerError);
  // The literal divider (no guard bit, see below) returns 61; kp = 0 + (30 * 8 >> 4) = 15,
  // v = 16 * 15 = 240 >= 128: outside.
  const FixedTest literal =
      vhdlTest(kFourBit, ray, tilted, {VhdlRegisters::Widened, TDivModel::Literal});
  CHECK(literal.verdict == FixedVerdict::Outside);
  CHECK(literal.t == 61);
}

TEST_CASE("BIH t_div: the model is floor(|a| 2^(w-2) / |b|) with the error bit", "[bih]") {
  // w = 7: q = floor(32 |a| / |b|), err when the signs differ or |a| >= |b|.
  CHECK(tDivide(3, 5, 7, TDivModel::Exact).q == 19);  // 96 / 5 = 19.2
  CHECK_FALSE(tDivide(3, 5, 7, TDivModel::Exact).err);
  CHECK(tDivide(-3, -5, 7, TDivModel::Exact).q == 19);
  CHECK(tDivide(-3, 5, 7, TDivModel::Exact).err);
  CHECK(tDivide(5, 5, 7, TDivModel::Exact).err);
  CHECK(tDivide(0, 0, 7, TDivModel::Exact).err);
  CHECK_FALSE(tDivide(0, 5, 7, TDivModel::Exact).err);
  CHECK(tDivide(0, -5, 7, TDivModel::Exact).err);  // sign 0 xor 1
}

TEST_CASE("BIH t_div: the literal listing equals the model for |b| <= 2^(w-2)", "[bih]") {
  // Every pair at w = 7 (|a|, |b| < 64) with |b| <= 32 and every sign: the non-restoring steps
  // keep each remainder in [-|b|, |b|), which the 6-bit window holds, so the quotient is exact.
  for (int64_t b = -32; b <= 32; ++b)
    for (int64_t a = -63; a <= 63; ++a) {
      const TDivResult literal = tDivide(a, b, 7, TDivModel::Literal);
      const TDivResult model = tDivide(a, b, 7, TDivModel::Exact);
      REQUIRE(literal.err == model.err);
      if (!model.err) REQUIRE(literal.q == model.q);
    }
  // 3 / 5, stage by stage (qn has 2w - 3 = 11 bits; the window of stage i is bits i+5..i):
  //   start 00001100000; stage 5 subtracts: 3 - 5 = -2 -> 62: 11111000000;
  //   4 adds (bit 10 = 1): 60 + 5 = 1: 10000010000; 3 subtracts (bit 9 = 0): 2 - 5 -> 61;
  //   2 adds: 58 + 5 = 63; 1 adds: 62 + 5 = 3; 0 subtracts: 6 - 5 = 1: 10110000001.
  //   q = not(bits 10..5 = 101100) = 010011 = 19 = floor(96 / 5).
  CHECK(tDivide(3, 5, 7, TDivModel::Literal).q == 19);
  // |b| = 34 > 32: stage 5: 1 - 34 = -33, which 6 bits cannot hold: 31, sign bit 0 (lost);
  // stage 4 subtracts: 62 - 34 = 28; 3: 56 - 34 = 22; 2: 44 - 34 = 10; 1: 20 - 34 -> 50;
  // 0 adds: 36 + 34 = 70 -> 6. qn = 00001000110, q = not(000010) = 111101 = 61, not 0.
  const TDivResult wrong = tDivide(1, 34, 7, TDivModel::Literal);
  CHECK_FALSE(wrong.err);
  CHECK(wrong.q == 61);
  CHECK(tDivide(1, 34, 7, TDivModel::Exact).q == 0);
}

}  // namespace rtu
