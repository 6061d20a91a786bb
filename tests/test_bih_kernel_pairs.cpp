// Seed 004's two kernels (kinds/bih/fixed_kernels.h) on random triangle and ray pairs: where the
// C99 listing and the VHDL decide differently, the difference must be one the listings explain
// (docs/triangles.md, "Fixed point (seed 004)"):
//   err       the VHDL's divider errs (t outside [0, 2^(n+1)) or its signs differ) where C99 hits;
//   zero t    C99's t is 0 (not ahead) where the VHDL, which has no t > 0 test, hits (C9);
//   sum one   the same u and v, with 1 <= u + v < 1 + 2^-(m-1): C99's `>> E` test accepts, the
//             VHDL's strict u + v < 1 does not (C10);
//   rounding  both ran the barycentric test on different t or k: the VHDL floors each product of
//             the numerator (C6) and multiplies t without its LSB (C8).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <sstream>
#include <string>

#include "kinds/bih/fixed_kernels.h"

namespace rtu {
namespace {

struct PairCounts {
  int pairs = 0, agree = 0, bothHit = 0, sameT = 0;
  int64_t largestTDifference = 0;  // between the kernels' t where both hit
  int err = 0, zeroT = 0, sumOne = 0, rounding = 0, unexplained = 0;
  int disagreements() const { return err + zeroT + sumOne + rounding + unexplained; }
};

bool ranBarycentrics(const FixedTest& test) {
  return test.verdict == FixedVerdict::Hit || test.verdict == FixedVerdict::Outside;
}

void classify(const FixedTest& c99, const FixedTest& vhdl, const FixedTriangleFormat& f,
              PairCounts& counts) {
  ++counts.pairs;
  if (c99.hit() == vhdl.hit()) {
    ++counts.agree;
    counts.bothHit += c99.hit();
    if (!c99.hit()) return;
    counts.sameT += c99.t == vhdl.t;
    counts.largestTDifference = std::max(counts.largestTDifference, std::abs(c99.t - vhdl.t));
  } else if (c99.hit() && vhdl.verdict == FixedVerdict::DividerError) {
    ++counts.err;
  } else if (vhdl.hit() && c99.verdict == FixedVerdict::NotAhead && c99.t == 0) {
    ++counts.zeroT;
  } else if (c99.hit() && c99.u == vhdl.u && c99.v == vhdl.v &&
             c99.u + c99.v >= (int64_t(1) << (f.m - 1 + f.E))) {
    ++counts.sumOne;
  } else if (ranBarycentrics(c99) && ranBarycentrics(vhdl) &&
             (c99.t != vhdl.t || c99.u != vhdl.u || c99.v != vhdl.v)) {
    ++counts.rounding;
  } else {
    ++counts.unexplained;
  }
}

// Random grid triangles, and rays from a random grid point towards a point of the triangle's
// plane at barycentrics uniform in [-0.05, 1.05]^2 (so about a tenth pass just outside an edge).
PairCounts comparePairs(const FixedTriangleFormat& format, int count, uint64_t seed) {
  std::mt19937_64 random(seed);
  const int64_t side = int64_t(1) << format.n;
  const auto coordinate = [&] { return static_cast<int64_t>(random() % uint64_t(side)); };
  const auto fraction = [&] { return -0.05 + 1.1 * double(random() >> 11) * 0x1.0p-53; };
  PairCounts counts;
  while (counts.pairs < count) {
    std::array<GridPoint, 3> x;
    for (auto& vertex : x) vertex = {coordinate(), coordinate(), coordinate()};
    const Projection projection = project(x, format, 0);
    if (!projection.triangle) continue;
    GridRay ray;
    ray.origin = {coordinate(), coordinate(), coordinate()};
    const double a = fraction(), b = fraction();
    double direction[3], length = 0;
    for (int k = 0; k < 3; ++k) {
      direction[k] = x[0][k] + a * (x[1][k] - x[0][k]) + b * (x[2][k] - x[0][k]) - ray.origin[k];
      length += direction[k] * direction[k];
    }
    if (length == 0) continue;
    for (int k = 0; k < 3; ++k)
      ray.omega[k] =
          std::lround(direction[k] / std::sqrt(length) * 0.999 * std::ldexp(1.0, format.m - 1));
    classify(c99Test(format, ray, *projection.triangle, kC99NoHitYet),
             vhdlTest(format, ray, *projection.triangle), format, counts);
  }
  return counts;
}

}  // namespace

std::string describe(const PairCounts& c) {
  std::ostringstream out;
  out << "agree " << c.agree << " (both hit " << c.bothHit << ", same t " << c.sameT
      << ", largest t difference " << c.largestTDifference << "); err " << c.err << ", zero t "
      << c.zeroT << ", sum one " << c.sumOne << ", rounding " << c.rounding;
  return out.str();
}

TEST_CASE("BIH kernels: C99 and VHDL on random pairs differ only as the listings explain",
          "[bih]") {
  SECTION("n = 8: triangles of about 100 grid units, each listing's rounding visible") {
    const PairCounts counts = comparePairs({8, 10, 4, 0, 4, FixedListing::Vhdl}, 10000, 27);
    INFO(describe(counts));
    CHECK(counts.unexplained == 0);
    // The kernels' t differ by a few units (the numerator's floors, t's LSB, divided by den),
    // which moves k by as much: rays within a few units of an edge, some % of these rays.
    CHECK(counts.disagreements() < counts.pairs / 10);
    CHECK(counts.bothHit > counts.pairs / 3);  // a triangle covers half the aimed square
  }
  SECTION("n = 30: triangles of about 2^29 units; a few units of rounding never decide") {
    const PairCounts counts = comparePairs(kVhdlFormat, 10000, 27);
    INFO(describe(counts));
    CHECK(counts.disagreements() == 0);
    CHECK(counts.bothHit > counts.pairs / 3);
  }
}

}  // namespace rtu
